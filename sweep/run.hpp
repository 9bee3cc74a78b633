#pragma once
// Running a sweep: output checks, resume, parallel evaluation with worker threads, atomic row
// appends and the final sorted CSV.

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "sweep/designs.hpp"
#include "sweep/results_file.hpp"
#include "sweep/row.hpp"

namespace rheomag::sweep {

/// A slice of the designs for job-array schedulers: ids with id % count == index.
struct Shard {
  long long index = 0;
  long long count = 1;
};

/// Parses "i/N" (0 <= i < N); InputError otherwise.
Shard parse_shard(const std::string& text);

/// How to run a sweep.
struct SweepRunOptions {
  int jobs = 0;                         ///< worker threads; 0 = all cores
  std::filesystem::path out_dir = ".";  ///< where the CSV (and .vtu files) go
  Shard shard;
  std::vector<ColumnGroup> extra_columns;  ///< later links' columns (e.g. the valve chain)
  std::ostream* progress = nullptr;        ///< progress reports (null: silent)
  bool progress_terminal = false;          ///< redrawn bar instead of plain lines
  bool handle_signals = true;  ///< SIGINT/SIGTERM: finish running designs, keep rows, stop
};

/// What a run did.
struct SweepSummary {
  std::filesystem::path csv;
  long long designs = 0;         ///< designs of this run (the shard's)
  long long resumed = 0;         ///< rows already in the CSV, skipped
  long long evaluated = 0;       ///< designs solved now
  long long errors = 0;          ///< error rows among those solved now
  long long meshes_built = 0;    ///< meshes generated now
  long long meshes_reused = 0;   ///< designs that reused a mesh of the same geometry
  long long solvers_reused = 0;  ///< designs solved on the previous design's solver (currents only)
  double seconds = 0.0;
  double designs_per_minute = 0.0;  ///< of the designs solved now
  bool interrupted = false;         ///< stopped by a signal: rows kept, the CSV not yet sorted
  int interrupt_signal = 0;         ///< the signal that stopped it (SIGINT, SIGTERM; 0: unknown)
};

/// The results file of a run: spec.csv in out_dir, or "<stem>.part-<i>-of-<N><ext>" for a shard.
std::filesystem::path results_path(const SweepSpec& spec, const std::filesystem::path& out_dir,
                                   const Shard& shard);

/// Directory of the per-design .vtu files ("<csv stem>_vtu" next to the CSV).
std::filesystem::path vtu_directory(const std::filesystem::path& csv);

/// Estimated bytes one CSV row of `layout` takes at most (numbers and a maximal error text).
double row_bytes_estimate(const RowLayout& layout);

/// Estimated .vtu bytes of one design of the base case (meshes the base case once).
double vtu_bytes_estimate(const SweepSpec& spec);

/// Everything decided before the first design runs.
struct PreparedSweep {
  std::filesystem::path csv;
  std::filesystem::path vtu_dir;   ///< empty without .vtu output
  RowsById rows;                   ///< finished rows (from an earlier, interrupted run)
  std::vector<long long> pending;  ///< ids still to run, ascending
  long long designs = 0;           ///< designs of this run
};

/// Checks the output directory (writable), reads finished rows of an earlier run, checks free
/// space for the pending rows (and .vtu files) and only then creates the CSV with its header.
/// Throws InputError before anything is written when a check fails.
PreparedSweep prepare_sweep(const SweepSpec& spec, const RowLayout& layout,
                            const DesignGenerator& designs, const SweepRunOptions& options);

/// Runs (or resumes) the sweep with worker threads. Design failures become error rows; I/O
/// failures throw InputError (rows written so far are kept).
SweepSummary run_sweep(const SweepSpec& spec, const SweepRunOptions& options);

/// Consecutive design ids a worker takes at once so that they share a mesh: for a factorial
/// sweep, the product of the level counts of the trailing axes that do not change the geometry
/// (keys under circuit, valve, fluid, damper, lumped, material, or named turns, circuit or
/// *_material); 1 for a Latin hypercube. Only speed depends on it, never the results.
long long mesh_sharing_block(const SweepSpec& spec);

/// True once SIGINT or SIGTERM arrived during a run with handle_signals.
bool stop_requested();

/// The signal that asked the current or last run to stop (0: none).
int stop_signal();

}  // namespace rheomag::sweep
