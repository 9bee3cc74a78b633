#include "sweep/run.hpp"

#include <algorithm>
#include <csignal>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "core/error.hpp"
#include "magnetostatics/domain.hpp"
#include "mesh/mesher.hpp"
#include "sweep/evaluate.hpp"
#include "sweep/progress.hpp"
#include "sweep/threads.hpp"

namespace rheomag::sweep {

namespace {

std::atomic<int> g_stop{0};  // the signal that asked the run to stop (0: none)
struct sigaction g_sweep_old_int {};
struct sigaction g_sweep_old_term {};

extern "C" void request_stop(int signal_number) {
  int expected = 0;
  g_stop.compare_exchange_strong(expected, signal_number);
  // A second signal gets the actions from before the run (the CLI's clean exit, which removes
  // temporaries; or the default), so a stuck design can still be stopped.
  sigaction(SIGINT, &g_sweep_old_int, nullptr);
  sigaction(SIGTERM, &g_sweep_old_term, nullptr);
}

/// Installs the stop handler for SIGINT and SIGTERM for its lifetime.
class StopSignals {
 public:
  StopSignals() {
    g_stop.store(0);
    struct sigaction action {};
    action.sa_handler = request_stop;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, &g_sweep_old_int);
    sigaction(SIGTERM, &action, &g_sweep_old_term);
  }
  ~StopSignals() {
    sigaction(SIGINT, &g_sweep_old_int, nullptr);
    sigaction(SIGTERM, &g_sweep_old_term, nullptr);
  }
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
};

bool is_ok_row(const std::string& row) {
  return row.size() >= 5 && row.compare(row.size() - 5, 5, ",ok,\n") == 0;
}

/// Bytes per node and per element of a results .vtu (binary appended VTK XML). Measured: 847 kB
/// for the annular_valve case (11386 nodes, 5615 P2 elements); these give 1.13 MB (1.3x margin).
constexpr double kVtuBytesPerNode = 60.0;
constexpr double kVtuBytesPerElement = 80.0;

}  // namespace

bool stop_requested() {
  return g_stop.load() != 0;
}

int stop_signal() {
  return g_stop.load();
}

Shard parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  Shard shard;
  try {
    if (slash == std::string::npos) throw std::invalid_argument("no slash");
    std::size_t used = 0;
    shard.index = std::stoll(text.substr(0, slash), &used);
    if (used != slash) throw std::invalid_argument("index");
    const std::string count = text.substr(slash + 1);
    shard.count = std::stoll(count, &used);
    if (used != count.size()) throw std::invalid_argument("count");
  } catch (const std::exception&) {
    throw InputError("--shard '" + text + "': expected i/N, e.g. 0/4");
  }
  if (shard.count < 1 || shard.index < 0 || shard.index >= shard.count) {
    throw InputError("--shard '" + text + "': expected 0 <= i < N");
  }
  return shard;
}

std::filesystem::path results_path(const SweepSpec& spec, const std::filesystem::path& out_dir,
                                   const Shard& shard) {
  std::filesystem::path csv = out_dir / spec.csv;
  if (shard.count > 1) {
    csv.replace_filename(csv.stem().string() + ".part-" + std::to_string(shard.index) + "-of-" +
                         std::to_string(shard.count) + csv.extension().string());
  }
  // The spec reader refused absolute paths and ".."; a symbolic link on the way (a folder, the
  // file, the _vtu folder) may still lead out of --out: resolve it and refuse what lands outside.
  std::error_code ec;
  std::filesystem::path root = std::filesystem::weakly_canonical(out_dir, ec);
  if (!root.empty() && root.filename().empty()) root = root.parent_path();  // "out/"
  std::vector<std::filesystem::path> written = {csv};
  if (spec.write_vtu) written.push_back(vtu_directory(csv));
  for (const std::filesystem::path& path : written) {
    const std::filesystem::path real = std::filesystem::weakly_canonical(path, ec);
    if (ec || root.empty()) continue;  // unreadable: the writers name the path
    const auto [r, p] = std::mismatch(root.begin(), root.end(), real.begin(), real.end());
    if (r != root.end())
      throw InputError(spec.csv_where + ": \"" + spec.csv + "\" writes " + path.string() +
                       ", which resolves through a symbolic link to " + real.string() +
                       ", outside the output folder " + root.string() +
                       " (--out); expected a path inside it");
  }
  return csv;
}

std::filesystem::path vtu_directory(const std::filesystem::path& csv) {
  return csv.parent_path() / (csv.stem().string() + "_vtu");
}

double row_bytes_estimate(const RowLayout& layout) {
  return 18.0 * static_cast<double>(layout.columns()) + static_cast<double>(kMaxErrorText) + 8.0;
}

double vtu_bytes_estimate(const SweepSpec& spec) {
  const cases::Problem closed = magnetostatics::close_domain(spec.base.problem);
  mesh::MeshOptions options;
  options.order = closed.order;
  options.min_gap_elements = closed.min_gap_elements;
  const mesh::Mesh m = mesh::generate_mesh(closed.geometry, options);
  return kVtuBytesPerNode * static_cast<double>(m.nodes.size()) +
         kVtuBytesPerElement * static_cast<double>(m.triangles.size());
}

long long mesh_sharing_block(const SweepSpec& spec) {
  if (spec.method != SweepMethod::factorial) return 1;
  auto keeps_geometry = [](const cases::CaseKey& key) {
    const std::string& top = key.path.front();
    const std::string& last = key.path.back();
    for (const char* section : {"circuit", "valve", "fluid", "damper", "lumped", "material"}) {
      if (top == section) return true;
    }
    const std::string suffix = "_material";
    return last == "turns" || last == "circuit" ||
           (last.size() >= suffix.size() &&
            last.compare(last.size() - suffix.size(), suffix.size(), suffix) == 0);
  };
  long long block = 1;
  for (std::size_t a = spec.axes.size(); a-- > 0 && keeps_geometry(spec.axes[a].key);) {
    block *= static_cast<long long>(spec.axes[a].levels.size());
  }
  return block;
}

PreparedSweep prepare_sweep(const SweepSpec& spec, const RowLayout& layout,
                            const DesignGenerator& designs, const SweepRunOptions& options) {
  PreparedSweep prepared;
  prepared.csv = results_path(spec, options.out_dir, options.shard);
  require_writable_directory(prepared.csv.parent_path());
  const Shard shard = options.shard;
  const std::string header = layout.header();
  bool exists = std::filesystem::exists(prepared.csv);
  bool repaired = false;
  if (exists) {
    const RowPrefix prefix = [&](long long id) {
      if (id >= designs.count() || id % shard.count != shard.index) return std::string();
      return layout.prefix(designs.design(id));
    };
    prepared.rows = read_finished_rows(prepared.csv, header, prefix, repaired);
  }
  for (long long id = shard.index; id < designs.count(); id += shard.count) {
    ++prepared.designs;
    if (!prepared.rows.count(id)) prepared.pending.push_back(id);
  }
  const double pending = static_cast<double>(prepared.pending.size());
  // The pending rows, then one sorted copy of the whole file (temp + rename) at the end.
  double bytes = row_bytes_estimate(layout) * (pending + static_cast<double>(prepared.designs));
  std::string what = std::to_string(prepared.pending.size()) + " CSV rows";
  if (spec.write_vtu) {
    prepared.vtu_dir = vtu_directory(prepared.csv);
    bytes += vtu_bytes_estimate(spec) * pending;
    what += " and .vtu files";
  }
  require_free_space(prepared.csv.parent_path(), bytes, what);
  if (!exists || repaired) write_sorted(prepared.csv, header, prepared.rows);
  if (spec.write_vtu) require_writable_directory(prepared.vtu_dir);
  return prepared;
}

SweepSummary run_sweep(const SweepSpec& spec, const SweepRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const RowLayout layout(spec, options.extra_columns);
  const DesignGenerator designs(spec);
  PreparedSweep prepared = prepare_sweep(spec, layout, designs, options);
  SweepSummary summary;
  summary.csv = prepared.csv;
  summary.designs = prepared.designs;
  summary.resumed = static_cast<long long>(prepared.rows.size());

  std::optional<StopSignals> signals;
  if (options.handle_signals) signals.emplace();
  RowAppender appender(prepared.csv);
  SweepProgress progress(static_cast<long long>(prepared.pending.size()), options.progress,
                         options.progress_terminal);
  unsigned jobs = options.jobs > 0 ? static_cast<unsigned>(options.jobs)
                                   : std::max(1u, std::thread::hardware_concurrency());
  jobs = static_cast<unsigned>(
      std::min<std::size_t>(jobs, std::max<std::size_t>(1, prepared.pending.size())));

  // Workers take blocks of consecutive pending designs (sharing a mesh), at most an even
  // share each so that all workers get work.
  const std::size_t share = (prepared.pending.size() + jobs - 1) / jobs;
  const std::size_t block = std::max<std::size_t>(
      1, std::min<std::size_t>(static_cast<std::size_t>(mesh_sharing_block(spec)), share));
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex mutex;  // guards prepared.rows, failure and the mesh counters
  std::exception_ptr failure;
  auto work = [&] {
    sweep_serial_openmp();  // parallel over designs, not inside each factorisation
    SweepEvaluator evaluator(spec, layout, prepared.vtu_dir);
    std::size_t i = 0, end = 0;
    while (!g_stop.load() && !failed.load()) {
      if (i == end) {
        i = next.fetch_add(block);
        end = std::min(i + block, prepared.pending.size());
      }
      if (i >= prepared.pending.size()) break;
      const Design design = designs.design(prepared.pending[i++]);
      const std::string row = evaluator.row(design);
      try {
        appender.append(row);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
        failed.store(true);
        break;
      }
      {
        std::lock_guard<std::mutex> lock(mutex);
        prepared.rows.emplace(design.id, row);
      }
      progress.record(is_ok_row(row));
    }
    std::lock_guard<std::mutex> lock(mutex);
    summary.meshes_built += evaluator.meshes_built();
    summary.meshes_reused += evaluator.meshes_reused();
    summary.solvers_reused += evaluator.solvers_reused();
  };
  std::vector<std::thread> workers;
  for (unsigned j = 1; j < jobs; ++j) workers.emplace_back(work);
  work();
  for (std::thread& t : workers) t.join();
  progress.finish();
  if (failure) std::rethrow_exception(failure);

  summary.evaluated = progress.done();
  summary.errors = progress.errors();
  summary.designs_per_minute = progress.rate_per_minute();
  summary.interrupted = static_cast<long long>(prepared.rows.size()) < summary.designs;
  if (summary.interrupted) summary.interrupt_signal = stop_signal();
  if (!summary.interrupted) write_sorted(prepared.csv, layout.header(), prepared.rows);
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace rheomag::sweep
