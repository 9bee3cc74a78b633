// rheomag sweep: batch design sweeps over case keys (parallel, resumable, sharded, MPI).

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "app/command.hpp"
#include "core/error.hpp"
#include "figures/sweep_grid.hpp"
#include "plot/figure.hpp"
#include "sweep/mpi.hpp"
#include "sweep/run.hpp"
#include "sweep/spec.hpp"
#include "sweep/valve_columns.hpp"

namespace {

using namespace rheomag::sweep;

struct SweepCommandOptions {
  std::string sweep_path;
  int jobs = 0;
  std::string out = ".";
  std::string shard;
  std::string plot;  // outputs against keys (.png / .svg)
  bool json = false;
  bool quiet = false;
};

void print_summary(const SweepSummary& s, bool json) {
  if (json) {
    nlohmann::json j{{"csv", s.csv.string()},
                     {"designs", s.designs},
                     {"resumed", s.resumed},
                     {"evaluated", s.evaluated},
                     {"errors", s.errors},
                     {"meshes_built", s.meshes_built},
                     {"meshes_reused", s.meshes_reused},
                     {"solvers_reused", s.solvers_reused},
                     {"seconds", s.seconds},
                     {"designs_per_minute", s.designs_per_minute},
                     {"interrupted", s.interrupted}};
    rheomag::app::print_json(j);
    return;
  }
  rheomag::app::print(
      "sweep: %lld designs (%lld from an earlier run), %lld solved now, %lld error rows\n",
      s.designs, s.resumed, s.evaluated, s.errors);
  if (s.meshes_built + s.meshes_reused > 0) {
    rheomag::app::print(
        "meshes: %lld generated, %lld reused (same geometry); solvers: %lld reused "
        "(only the currents changed)\n",
        s.meshes_built, s.meshes_reused, s.solvers_reused);
  }
  rheomag::app::print("%.1f s, %.1f designs/min\nresults: %s\n", s.seconds, s.designs_per_minute,
                      s.csv.c_str());
  if (s.interrupted) {
    rheomag::app::print(
        "interrupted: every finished row is kept; run the same command to resume\n");
  }
}

void run(const SweepCommandOptions& o) {
  if (!o.plot.empty() && !rheomag::plot::is_picture_path(o.plot))
    throw rheomag::InputError("--plot: expected a file name ending in .png or .svg");
  const SweepSpec spec = read_sweep(o.sweep_path);
  SweepRunOptions options;
  options.jobs = o.jobs;
  options.out_dir = o.out;
  options.extra_columns = valve_columns(spec);  // pressure drop and coil, with a [valve] table
  if (!o.shard.empty()) options.shard = parse_shard(o.shard);
  options.progress = o.quiet ? nullptr : &std::cerr;
  options.progress_terminal = ::isatty(STDERR_FILENO) == 1;
  SweepSummary summary;
  if (launched_with_mpi()) {
    bool is_root = false;
    summary = run_sweep_mpi(spec, options, is_root);
    if (!is_root) return;
  } else {
    summary = run_sweep(spec, options);
  }
  if (!o.plot.empty()) {
    std::vector<std::string> keys;
    for (const SweepAxis& axis : spec.axes) keys.push_back(axis.key.written);
    rheomag::figures::sweep_figure(rheomag::figures::read_sweep_table(summary.csv), keys, 560, 340)
        .write(o.plot, "--plot");
  }
  print_summary(summary, o.json);
  if (summary.interrupted) {
    // 128 + the signal, as a shell reports a process ended by it (130 SIGINT, 143 SIGTERM).
    std::cout.flush();
    std::exit(128 + (summary.interrupt_signal > 0 ? summary.interrupt_signal : SIGINT));
  }
}

const bool sweep_registered = rheomag::app::register_command([](CLI::App& root) {
  auto options = std::make_shared<SweepCommandOptions>();
  CLI::App* cmd = root.add_subcommand(
      "sweep",
      "Batch design sweep: a base case plus axes over any of its keys (lists, ranges, Latin "
      "hypercube or full factorial; format in docs/sweep-format.md). Solves every design in "
      "parallel and writes one CSV row per design (inputs, |B| per gap, flux linkage and "
      "inductance per circuit; with a [valve] table in the base case also the pressure drop at "
      "its flow and the coil's resistance, L/R and power; status, error text); a failing design "
      "becomes an error row. "
      "Interrupted (Ctrl-C, kill), every finished row is kept and the same command resumes. "
      "Under 'mpirun -n K' rank 0 hands designs to the other ranks and writes one CSV.");
  cmd->add_option("sweep", options->sweep_path, "sweep file (.toml)")->required();
  cmd->add_option("--jobs,-j", options->jobs, "designs solved at once (default: all cores)")
      ->check(rheomag::app::in_domain(rheomag::Domain::non_negative().whole()));
  cmd->add_option("--out,-o", options->out,
                  "output directory (created if missing; default: current directory)");
  cmd->add_option("--shard", options->shard,
                  "run only designs with id % N == i and write <csv stem>.part-i-of-N.csv "
                  "(for job arrays); e.g. --shard 0/4");
  cmd->add_flag("--quiet,-q", options->quiet, "no progress reports on stderr");
  cmd->add_option("--plot", options->plot,
                  "draw every output column against every swept key (a grid of panels) from the "
                  "results to this .png or .svg")
      ->check(rheomag::app::output_file_in_writable_folder());
  cmd->add_flag("--json", options->json, "print the run summary as one JSON object");
  cmd->callback([options] { run(*options); });
});

}  // namespace
