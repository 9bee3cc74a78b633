// Time of one whole diagnosis (issue 5 target: a 20 000-sample recording in under 30 s on the
// 2-core machine). The recording is the bundled bypass rig of paper 001
// (cases/rigs/bypass_cylinder.toml: 2e-7 m^3 of air, 2e4 Pa pressure noise) at 1 kHz for 20 s,
// +-25 mm at 0.5 Hz, current steps 0/0.5/1 A every 2 s, simulated in-process; the sidecar map is
// the spec's. Set RHEOMAG_DIAGNOSE_TRACE=1 to print each candidate fit and its time.
// Reports wall time (the Google Benchmark column) and the process CPU time as counters.

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <ctime>
#include <iostream>
#include <string>

#include "coupling/simulation_spec.hpp"
#include "diagnose/diagnose_run.hpp"
#include "lumped/recording.hpp"
#include "lumped/signals.hpp"

namespace {

using namespace rheomag;

/// The recording `rheomag simulate cases/rigs/bypass_cylinder.toml ... --duration D --rate R`
/// would write.
lumped::Recording bypass_recording(double duration, double rate) {
  const auto spec = coupling::read_simulation_spec(std::string(RHEOMAG_SOURCE_DIR) +
                                                   "/cases/rigs/bypass_cylinder.toml");
  lumped::Recording drive;
  drive.t = lumped::uniform_times(duration, rate);
  lumped::add_signal(drive, "displacement=sine:amplitude=0.025,frequency=0.5");
  lumped::add_signal(drive, "current=steps:levels=0/0.5/1,period=2");
  auto rec = coupling::simulate_spec(spec, drive);
  rec.csv_path = "bypass_cylinder.csv";
  rec.meta.sidecar_path = "bypass_cylinder.toml";
  return rec;
}

double cpu_seconds() {
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

void BM_Diagnose(benchmark::State& state) {
  const double samples = static_cast<double>(state.range(0));
  const auto rec = bypass_recording(samples / 1000.0, 1000.0);
  diagnose::DiagnoseOptions options;
  if (std::getenv("RHEOMAG_DIAGNOSE_TRACE"))
    options.progress = [](const rheomag::ProgressEvent& e) {
      std::cerr << "diagnose: " << e.stage << " " << e.detail << "\n";
    };
  double cpu = 0.0, fit = 0.0;
  std::string named;
  for (auto _ : state) {
    const double c0 = cpu_seconds();
    const auto d = diagnose::diagnose(rec, options);
    cpu += cpu_seconds() - c0;
    fit = d.final_fit_percent;
    named.clear();
    for (const auto& f : d.findings) named += f.effect->name() + " ";
  }
  state.counters["cpu_s"] = cpu / static_cast<double>(state.iterations());
  state.counters["final_fit"] = fit;
  state.SetLabel(named.empty() ? "none" : named);
}
BENCHMARK(BM_Diagnose)->Arg(20000)->Arg(5000)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
