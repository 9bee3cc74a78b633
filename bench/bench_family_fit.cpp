// Benchmarks of issue 14's speed targets on the UTFSM damper recordings (shared/data/utfsm):
// single grey-box fits on 25 mm / 0.5 Hz / 1 A (target < 5 s wall) and the 15-recording 25 mm
// family fit (target < 30 s wall), with the FIT of the prediction of 10 mm / 1 Hz as counters.
// "Time" is wall time, "CPU" the whole process's CPU time (the starts run on every core).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <vector>

#include "identify/current_dependent_fit.hpp"
#include "identify/greybox.hpp"
#include "lumped/recording_io.hpp"

using namespace rheomag::lumped;
using namespace rheomag::identify;

namespace {

const std::string kData = std::string(RHEOMAG_SHARED_DIR) + "/data/utfsm/";
const std::vector<std::string> kCurrents = {"0A", "0x25A", "0x5A", "0x75A", "1A"};
const std::vector<std::string> kModels = {"damper",  "bouc-wen", "lugre",      "dahl",
                                          "maxwell", "bingham",  "bi-viscous", "tanh"};

void BM_SingleFit(benchmark::State& state) {
  const std::string model = kModels[static_cast<std::size_t>(state.range(0))];
  state.SetLabel(model);
  const Recording train = read_recording(kData + "25mm0x5Hz1A.csv");
  const Recording other = read_recording(kData + "10mm1Hz1A.csv");
  for (auto _ : state) {
    const GreyboxFit fit = fit_greybox(train, model);
    state.counters["train_fit_percent"] = fit.train.fit_percent;
    state.counters["predicted_fit_percent"] =
        compute_metrics(other.column("force"), simulate_greybox(other, fit)).fit_percent;
  }
}
BENCHMARK(BM_SingleFit)
    ->DenseRange(0, 7)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

void BM_FamilyFit25mm(benchmark::State& state) {
  const std::string model = kModels[static_cast<std::size_t>(state.range(0))];
  state.SetLabel(model);
  std::vector<Recording> training, prediction;
  for (const char* f : {"25mm0x1Hz", "25mm0x25Hz", "25mm0x5Hz"})
    for (const std::string& c : kCurrents)
      training.push_back(read_recording(kData + f + c + ".csv"));
  for (const std::string& c : kCurrents)
    prediction.push_back(read_recording(kData + "10mm1Hz" + c + ".csv"));
  for (auto _ : state) {
    const FamilyFit r = fit_current_dependent(training, model, prediction);
    double lowest = 100.0;
    for (const FamilyMember& m : r.predicted) lowest = std::min(lowest, m.metrics.fit_percent);
    state.counters["lowest_predicted_fit_percent"] = lowest;
  }
}
BENCHMARK(BM_FamilyFit25mm)
    ->DenseRange(0, 7)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
