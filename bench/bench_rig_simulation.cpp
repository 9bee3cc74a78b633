// Time of one free-run rig simulation (lumped::simulate_rig of the diagnosis model's spec) on an
// edge-rich real recording: shared/data/dyke1996/ranran_50.csv (74 068 samples at 3 kHz, random
// on/off command with about 1 100 edges), baseline (-1), baseline + each candidate effect (its
// enum value) and compressibility + fluid_inertia (-2) at the starting values, with the
// error-controlled rosenbrock4 (third argument 0) or 1 or 2 fixed SDIRK2 steps per sample
// (lumped/ode_grid.hpp). Counter max_diff_rel: the largest difference from the rosenbrock4 output
// over the output's rms; rms_diff_rel: the rms difference over the rms. The diagnosis runs
// thousands of such simulations.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "diagnose/candidate_registry.hpp"
#include "diagnose/diagnose_model.hpp"
#include "lumped/recording_excerpt.hpp"
#include "lumped/recording_io.hpp"
#include "lumped/rig_model.hpp"

namespace {

using namespace rheomag;

const lumped::Recording& dyke_recording() {
  static const lumped::Recording rec = [] {
    auto r =
        lumped::read_csv_samples(std::string(RHEOMAG_SHARED_DIR) + "/data/dyke1996/ranran_50.csv");
    r.meta = lumped::read_sidecar(std::string(RHEOMAG_SOURCE_DIR) +
                                  "/tests/data/diagnosis/dyke1996.toml");
    return r;
  }();
  return rec;
}

void BM_DykeSimulation(benchmark::State& state) {
  const auto samples = static_cast<std::size_t>(state.range(0));
  const int effect = static_cast<int>(state.range(1));
  const auto rec = lumped::excerpt(dyke_recording(), {0, samples});
  const diagnose::DiagnosisModel model(rec);
  std::vector<const diagnose::Candidate*> effects;
  if (effect >= 0)
    effects.push_back(diagnose::registered_candidates().at(static_cast<std::size_t>(effect)));
  if (effect == -2)
    effects = {&diagnose::candidate_named("compressibility"),
               &diagnose::candidate_named("fluid_inertia")};
  std::vector<double> values;
  for (const auto& p : model.layout(effects)) values.push_back(p.nominal);
  auto spec = model.spec(effects, values);
  spec.grid_substeps = static_cast<int>(state.range(2));
  std::vector<double> y;
  for (auto _ : state) y = lumped::simulate_rig(spec, rec).column(model.output_column());
  // Largest difference from the adaptive (error-controlled) simulation, in output rms.
  spec.grid_substeps = 0;
  const auto ref = lumped::simulate_rig(spec, rec).column(model.output_column());
  double diff = 0.0, rms = 0.0, rms_diff = 0.0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    diff = std::max(diff, std::abs(y[k] - ref[k]));
    rms += ref[k] * ref[k];
    rms_diff += (y[k] - ref[k]) * (y[k] - ref[k]);
  }
  state.counters["rms_diff_rel"] = std::sqrt(rms_diff / rms);
  state.counters["max_diff_rel"] = diff / std::sqrt(rms / static_cast<double>(y.size()));
  std::string label = effects.empty() ? "baseline" : "";
  for (auto e : effects) label += (label.empty() ? "" : "+") + e->name();
  state.SetLabel(label);
}
BENCHMARK(BM_DykeSimulation)
    ->ArgsProduct({{6000, 74068}, {-2, -1, 0, 1, 3, 4, 5, 6, 7}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
