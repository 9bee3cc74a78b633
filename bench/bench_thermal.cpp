// The thermal side of the reference valve (cases/annular_valve.toml) against its magnetic solve
// on the same mesh (issue 32: a steady thermal solve costs no more than the magnetic one):
// the nonlinear magnetic solve at 1 A from A = 0, the thermal set-up (thermal model, assembly,
// CHOLMOD analysis) with one steady solve, and a further steady solve with new sources (one
// substitution, what each fixed-point iteration costs). CPU seconds per run as a counter.

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include "case/case_file.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "thermal/device_regions.hpp"
#include "thermal/heat_solver.hpp"
#include "thermal/model_from_case.hpp"

namespace {

using namespace rheomag;

/// The reference valve solved once at 1 A (its mesh and problem are the thermal model's).
const magnetostatics::SolveResult& valve() {
  static const cases::Case c = cases::load_case(RHEOMAG_SOURCE_DIR "/cases/annular_valve.toml");
  static const magnetostatics::SolveResult solved = magnetostatics::solve_problem(c.problem);
  return solved;
}

/// User + system CPU time of this process [s].
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

/// 5 W in the coil regions as source densities.
std::vector<double> coil_heat(const cases::Problem& problem, const mesh::Mesh& mesh, double watts) {
  const std::vector<double> volume = thermal::region_volumes(problem, mesh);
  std::vector<double> power(problem.regions.size(), 0.0);
  thermal::spread_power(watts, thermal::coil_regions(problem), volume, power);
  return thermal::source_densities(power, volume);
}

void BM_ValveMagneticSolve(benchmark::State& state) {
  magnetostatics::MagnetostaticSolver& solver = *valve().solver;
  double cpu = 0.0;
  for (auto _ : state) {
    const double before = cpu_seconds();
    benchmark::DoNotOptimize(solver.solve().flux_linkage.data());
    cpu += cpu_seconds() - before;
  }
  state.counters["unknowns"] = solver.dofs().free_count();
  state.counters["cpu_s"] = cpu / static_cast<double>(state.iterations());
}
BENCHMARK(BM_ValveMagneticSolve)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ValveThermalSetupAndSteady(benchmark::State& state) {
  const auto& solver = *valve().solver;
  const std::vector<double> q = coil_heat(solver.problem(), solver.mesh(), 5.0);
  double cpu = 0.0;
  int unknowns = 0;
  for (auto _ : state) {
    const double before = cpu_seconds();
    thermal::HeatSolver heat(solver.problem(), solver.mesh(),
                             thermal::build_heat_model(solver.problem(), {}, 0.55));
    heat.set_sources(q);
    benchmark::DoNotOptimize(heat.steady().source_power);
    cpu += cpu_seconds() - before;
    unknowns = heat.unknowns();
  }
  state.counters["unknowns"] = unknowns;
  state.counters["cpu_s"] = cpu / static_cast<double>(state.iterations());
}
BENCHMARK(BM_ValveThermalSetupAndSteady)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ValveThermalResolve(benchmark::State& state) {
  const auto& solver = *valve().solver;
  thermal::HeatSolver heat(solver.problem(), solver.mesh(),
                           thermal::build_heat_model(solver.problem(), {}, 0.55));
  heat.set_sources(coil_heat(solver.problem(), solver.mesh(), 5.0));
  heat.steady();
  double watts = 5.0;
  for (auto _ : state) {
    watts += 0.01;
    heat.set_sources(coil_heat(solver.problem(), solver.mesh(), watts));
    benchmark::DoNotOptimize(heat.steady().source_power);
  }
}
BENCHMARK(BM_ValveThermalResolve)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
