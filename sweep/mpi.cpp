#include "sweep/mpi.hpp"

#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "sweep/evaluate.hpp"
#include "sweep/progress.hpp"
#include "sweep/threads.hpp"

#ifdef RHEOMAG_HAVE_MPI
#define OMPI_SKIP_MPICXX 1  // the C API only (the deprecated C++ bindings warn under -Wextra)
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <csignal>
#endif

namespace rheomag::sweep {

bool mpi_built() {
#ifdef RHEOMAG_HAVE_MPI
  return true;
#else
  return false;
#endif
}

bool launched_with_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    if (const char* value = std::getenv(name)) {
      if (std::atol(value) > 1) return true;
    }
  }
  return false;
}

#ifdef RHEOMAG_HAVE_MPI

namespace {

constexpr int kTagRow = 1;   // worker -> rank 0: the row of the last design ("" at first)
constexpr int kTagWork = 2;  // rank 0 -> worker: next design id, -1 = stop

std::atomic<int> g_mpi_stop{0};  // the signal that asked the run to stop (0: none)
extern "C" void request_mpi_stop(int signal_number) {
  int expected = 0;
  g_mpi_stop.compare_exchange_strong(expected, signal_number);
}

/// Starts MPI unless this process already has (the 3D solver's AMS starts it on first use), and
/// then ends it on every path out of run_sweep_mpi.
struct MpiSession {
  MpiSession() {
    int initialized = 0;
    MPI_Initialized(&initialized);
    owned = !initialized;
    if (owned) MPI_Init(nullptr, nullptr);
  }
  ~MpiSession() {
    if (owned) MPI_Finalize();
  }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  bool owned = false;  ///< MPI_Init was called here
};

long long row_id(const std::string& row) {
  return std::atoll(row.c_str());
}

SweepSummary run_root(const SweepSpec& spec, const SweepRunOptions& options, int ranks) {
  const auto start = std::chrono::steady_clock::now();
  const RowLayout layout(spec, options.extra_columns);
  const DesignGenerator designs(spec);
  PreparedSweep prepared;
  int status = 0;
  std::string message;
  try {
    prepared = prepare_sweep(spec, layout, designs, options);
  } catch (const InputError& e) {
    status = 1;
    message = e.what();
  }
  MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (status != 0) throw InputError(message);

  SweepSummary summary;
  summary.csv = prepared.csv;
  summary.designs = prepared.designs;
  summary.resumed = static_cast<long long>(prepared.rows.size());
  RowAppender appender(prepared.csv);
  SweepProgress progress(static_cast<long long>(prepared.pending.size()), options.progress,
                         options.progress_terminal);
  std::size_t next = 0;
  int active = ranks - 1;
  bool failed = false;
  std::string failure;
  while (active > 0) {
    MPI_Status probe;
    MPI_Probe(MPI_ANY_SOURCE, kTagRow, MPI_COMM_WORLD, &probe);
    int length = 0;
    MPI_Get_count(&probe, MPI_CHAR, &length);
    std::string row(static_cast<std::size_t>(length), '\0');
    MPI_Recv(row.data(), length, MPI_CHAR, probe.MPI_SOURCE, kTagRow, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    if (!row.empty() && !failed) {
      try {
        appender.append(row);
        prepared.rows.emplace(row_id(row), row);
        progress.record(row.size() >= 5 && row.compare(row.size() - 5, 5, ",ok,\n") == 0);
      } catch (const InputError& e) {
        failed = true;
        failure = e.what();
      }
    }
    long long id = -1;
    if (!failed && g_mpi_stop.load() == 0 && next < prepared.pending.size()) {
      id = prepared.pending[next++];
    }
    MPI_Send(&id, 1, MPI_LONG_LONG, probe.MPI_SOURCE, kTagWork, MPI_COMM_WORLD);
    if (id < 0) --active;
  }
  progress.finish();
  if (failed) throw InputError(failure);
  summary.evaluated = progress.done();
  summary.errors = progress.errors();
  summary.designs_per_minute = progress.rate_per_minute();
  summary.interrupted = static_cast<long long>(prepared.rows.size()) < summary.designs;
  if (summary.interrupted) summary.interrupt_signal = g_mpi_stop.load();
  if (!summary.interrupted) write_sorted(prepared.csv, layout.header(), prepared.rows);
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

void run_worker(const SweepSpec& spec, const SweepRunOptions& options) {
  int status = 0;
  MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (status != 0) return;
  const RowLayout layout(spec, options.extra_columns);
  const DesignGenerator designs(spec);
  const std::filesystem::path vtu_dir =
      spec.write_vtu ? vtu_directory(results_path(spec, options.out_dir, options.shard))
                     : std::filesystem::path();
  SweepEvaluator evaluator(spec, layout, vtu_dir);
  std::string row;
  while (true) {
    MPI_Send(row.data(), static_cast<int>(row.size()), MPI_CHAR, 0, kTagRow, MPI_COMM_WORLD);
    long long id = -1;
    MPI_Recv(&id, 1, MPI_LONG_LONG, 0, kTagWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (id < 0) break;
    row = evaluator.row(designs.design(id));
  }
}

}  // namespace

SweepSummary run_sweep_mpi(const SweepSpec& spec, const SweepRunOptions& options, bool& is_root) {
  sweep_serial_openmp();  // parallel over ranks, not inside each factorisation
  MpiSession session;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  is_root = rank == 0;
  if (ranks < 2) {
    throw InputError(
        "MPI run with a single rank; start with mpirun -n K (K >= 2) or without mpirun");
  }
  if (options.handle_signals) {
    // Finish the running designs, keep their rows, stop handing out new ones.
    g_mpi_stop.store(0);
    std::signal(SIGINT, request_mpi_stop);
    std::signal(SIGTERM, request_mpi_stop);
  }
  if (!is_root) {
    run_worker(spec, options);
    return {};
  }
  return run_root(spec, options, ranks);
}

#else

SweepSummary run_sweep_mpi(const SweepSpec&, const SweepRunOptions&, bool& is_root) {
  is_root = true;
  throw InputError(
      "this rheomag was built without MPI; install libopenmpi-dev and rebuild, or run the sweep "
      "without mpirun (use --jobs, or --shard i/N for job arrays)");
}

#endif

}  // namespace rheomag::sweep
