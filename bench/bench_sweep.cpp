// Sweep throughput (designs per minute) on the annular valve of paper 000 at its default mesh
// (cases/annular_valve.toml: P2, 4 elements across the gaps), 1 vs 2 worker threads:
// - currents: 16 currents of one geometry (one mesh per worker, reused by the other designs);
// - geometry: 8 channel widths x 2 currents (a new mesh for every width);
// - valve: the geometry sweep with the valve chain's columns (dp, R, L/R, power from the case's
//   [valve] table, evaluated from each design's own field solve).
// Counters: designs_per_min = designs / wall time x 60; cpu_s_per_design = process CPU time
// (user + sys, all threads) per design, the number to compare on a busy machine.

#include <benchmark/benchmark.h>
#include <stdlib.h>
#include <time.h>

#include <filesystem>
#include <string>

#include "sweep/run.hpp"
#include "sweep/spec.hpp"
#include "sweep/valve_columns.hpp"

namespace {

using namespace rheomag::sweep;

std::string sweep_text(bool geometry) {
  const std::string base = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";
  std::string text = "[sweep]\nbase = \"" + base + "\"\n";
  if (geometry) {
    text += "[[axis]]\nkey = \"geometry.gap_width\"\nstart = 0.6\nstop = 1.3\ncount = 8\n";
    text += "[[axis]]\nkey = \"circuit.current\"\nvalues = [0.5, 1.0]\n";
  } else {
    text += "[[axis]]\nkey = \"circuit.current\"\nstart = 0.1\nstop = 1.6\ncount = 16\n";
  }
  return text;
}

double process_cpu_seconds() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void run(benchmark::State& state, bool geometry, bool valve = false) {
  const SweepSpec spec = parse_sweep(sweep_text(geometry), "bench_sweep.toml");
  double designs = 0.0, seconds = 0.0, reused = 0.0;
  const double cpu_start = process_cpu_seconds();
  for (auto _ : state) {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "rheomag-bench-sweep-XXXXXX").string();
    const std::filesystem::path dir = ::mkdtemp(pattern.data());
    SweepRunOptions options;
    options.jobs = static_cast<int>(state.range(0));
    options.out_dir = dir;
    options.handle_signals = false;
    if (valve) options.extra_columns = valve_columns(spec);
    const SweepSummary summary = run_sweep(spec, options);
    designs += static_cast<double>(summary.evaluated);
    seconds += summary.seconds;
    reused += static_cast<double>(summary.meshes_reused);
    std::filesystem::remove_all(dir);
  }
  state.counters["designs_per_min"] = 60.0 * designs / seconds;
  state.counters["cpu_s_per_design"] = (process_cpu_seconds() - cpu_start) / designs;
  state.counters["meshes_reused"] = reused / static_cast<double>(state.iterations());
}

void BM_SweepCurrents(benchmark::State& state) {
  run(state, false);
}
void BM_SweepGeometry(benchmark::State& state) {
  run(state, true);
}
void BM_SweepGeometryValve(benchmark::State& state) {
  run(state, true, true);
}

BENCHMARK(BM_SweepCurrents)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("jobs")
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);
BENCHMARK(BM_SweepGeometry)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("jobs")
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);
BENCHMARK(BM_SweepGeometryValve)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("jobs")
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

}  // namespace
