// Benchmarks of the lumped dynamics (issue 4 targets: simulation < 0.1 s, Bouc-Wen fit < 5 s):
// 10 s at 1 kHz of the bypass-cylinder rig (cases/rigs/bypass_cylinder.toml, compressible, with
// air), and a Bouc-Wen fit to shared/data/mrdamper (3499 samples; train on the first 2000).

#include <benchmark/benchmark.h>

#include <string>

#include "coupling/simulation_spec.hpp"
#include "identify/greybox.hpp"
#include "lumped/recording_io.hpp"
#include "lumped/signals.hpp"

using namespace rheomag::lumped;
using namespace rheomag::identify;
using namespace rheomag::coupling;

static void BM_SimulateBypassRig10s1kHz(benchmark::State& state) {
  const SimulationSpec spec =
      read_simulation_spec(std::string(RHEOMAG_SOURCE_DIR) + "/cases/rigs/bypass_cylinder.toml");
  Recording drive;
  drive.t = uniform_times(10.0, 1000.0);
  add_signal(drive, "displacement=sine:amplitude=0.025,frequency=0.75");
  add_signal(drive, "current=steps:levels=0/0.25/0.5/0.75/1,period=2");
  for (auto _ : state) benchmark::DoNotOptimize(simulate_spec(spec, drive));
}
BENCHMARK(BM_SimulateBypassRig10s1kHz)->Unit(benchmark::kMillisecond);

static void BM_FitBoucWenMrdamper(benchmark::State& state) {
  const Recording rec =
      read_recording(std::string(RHEOMAG_SHARED_DIR) + "/data/mrdamper/mrdamper.csv");
  GreyboxOptions options;
  options.train = SampleRange{0, 2000};
  options.starts = static_cast<int>(state.range(0));
  options.threads = static_cast<int>(state.range(1));  // 0: one per core
  for (auto _ : state) {
    GreyboxFit fit = fit_greybox(rec, "bouc-wen", options);
    state.counters["train_fit_percent"] = fit.train.fit_percent;
    state.counters["validation_fit_percent"] =
        compute_metrics(rec.column("force"), fit.simulated, SampleRange{2000, rec.t.size()})
            .fit_percent;
  }
}
// Arguments: starts, threads (0 = one per core). Wall time is the target (issue: under 5 s); the
// CPU column is the whole process's (all start threads).
BENCHMARK(BM_FitBoucWenMrdamper)
    ->ArgNames({"starts", "threads"})
    ->Args({1, 1})
    ->Args({4, 1})
    ->Args({4, 0})
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
