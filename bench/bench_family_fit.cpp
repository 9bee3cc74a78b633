// Benchmarks of issue 14's speed targets on the UTFSM damper recordings (shared/data/utfsm):
// single grey-box fits on 25 mm / 0.5 Hz / 1 A (target < 5 s wall) and the 15-recording 25 mm
// family fit (target < 30 s wall), with the FIT of the prediction of 10 mm / 1 Hz as counters;
// and issue 35's cross-validated family fit of the 25 mm tests (`fit-family --cross-validate`,
// damper, 2 starts), cold refits against refits started from the other half's fit.
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

/// The 15 utfsm 25 mm recordings (0.1, 0.25, 0.5 Hz at every current).
std::vector<Recording> recordings_25mm() {
  std::vector<Recording> training;
  for (const char* f : {"25mm0x1Hz", "25mm0x25Hz", "25mm0x5Hz"})
    for (const std::string& c : kCurrents)
      training.push_back(read_recording(kData + f + c + ".csv"));
  return training;
}

void BM_FamilyFit25mm(benchmark::State& state) {
  const std::string model = kModels[static_cast<std::size_t>(state.range(0))];
  state.SetLabel(model);
  const std::vector<Recording> training = recordings_25mm();
  std::vector<Recording> prediction;
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

/// `fit-family 25mm*.csv --model damper --cross-validate` (2 starts, every 4th sample) with
/// --refit-iterations = the argument (0: cold refits from nominal, as before issue 35).
void BM_CrossValidate25mm(benchmark::State& state) {
  const std::vector<Recording> training = recordings_25mm();
  FamilyFitOptions options;
  options.greybox.starts = 2;
  options.cross_validate = true;
  options.refit_iterations = static_cast<int>(state.range(0));
  state.SetLabel(options.refit_iterations == 0 ? "cold refits" : "refits from the other half");
  for (auto _ : state) {
    const FamilyFit r = fit_current_dependent(training, "damper", {}, options);
    std::vector<double> held;
    for (const FamilyMember& m : r.held_out) held.push_back(m.metrics.fit_percent);
    std::sort(held.begin(), held.end());
    state.counters["lowest_held_out_fit_percent"] = held.front();
    state.counters["median_held_out_fit_percent"] = held[held.size() / 2];
  }
}
BENCHMARK(BM_CrossValidate25mm)
    ->Arg(0)
    ->Arg(10)
    ->Arg(30)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace
