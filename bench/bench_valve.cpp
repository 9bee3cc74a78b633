// Benchmarks of the annular reference valve (cases/annular_valve.toml, paper 000) at its default
// mesh: the whole solve_problem call (close domain, mesh, setup, nonlinear solve, results), the
// nonlinear solve alone on a built solver, and a 21-point current sweep. Counters: DOFs, Newton
// iterations, numeric factorisations, CPU seconds (user + sys of the process) per iteration and
// the process's peak resident memory (getrusage ru_maxrss, MiB).

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <vector>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "magnetostatics/solve_problem.hpp"

// The bundled case carries sections of later layers ([valve], [optimise]), which the program
// registers; this benchmark links only the layers below and registers them itself.
const bool kLaterSectionsRegistered = rheomag::cases::register_case_section("valve") &&
                                      rheomag::cases::register_case_section("optimise");

namespace {

using namespace rheomag::magnetostatics;
using namespace rheomag::cases;

/// The reference valve case, read once.
const Case& valve_case() {
  static const Case c = load_case(RHEOMAG_SOURCE_DIR "/cases/annular_valve.toml");
  return c;
}

/// User + system CPU time of this process [s].
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

/// Peak resident set size of this process so far [MiB] (Linux reports ru_maxrss in KiB).
double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/// Counters common to the valve benchmarks.
void set_counters(benchmark::State& state, const MagnetostaticSolver& solver, double cpu,
                  int factorizations) {
  const double runs = static_cast<double>(state.iterations());
  state.counters["dofs"] = solver.dofs().free_count();
  state.counters["elements"] = static_cast<double>(solver.mesh().triangles.size());
  state.counters["factorisations"] = factorizations / runs;
  state.counters["cpu_s"] = cpu / runs;
  state.counters["peak_MiB"] = peak_rss_mib();
}

/// Whole solve_problem at 1 A as `rheomag solve` runs it: domain closing, meshing, solver setup
/// (pattern, symbolic analysis), Newton from A = 0, incremental inductance, results.
void BM_AnnularValveSolveProblem(benchmark::State& state) {
  const Problem& problem = valve_case().problem;
  SolveResult last;
  double cpu = 0.0;
  int factorizations = 0;
  for (auto _ : state) {
    const double before = cpu_seconds();
    last = solve_problem(problem);
    cpu += cpu_seconds() - before;
    factorizations += last.solver->factorizations();
    benchmark::DoNotOptimize(last.results.gaps.data());
  }
  set_counters(state, *last.solver, cpu, factorizations);
  state.counters["newton"] = last.solution.newton.iterations;
  state.counters["mesh_s"] = last.mesh_seconds;
}
BENCHMARK(BM_AnnularValveSolveProblem)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Whole solve_problem on a finer mesh: every target size divided by the first argument (8:
/// about 4e5 nodes); second argument 1: nested iteration (the default above 2e5 nodes), 0: from
/// A = 0 (nested_above = 0). Counters as above, plus the coarse levels' meshing inside cpu_s.
void BM_AnnularValveFineSolveProblem(benchmark::State& state) {
  SolveOptions options;
  options.mesh.size_scale = 1.0 / static_cast<double>(state.range(0));
  if (state.range(1) == 0) options.nested_above = 0;
  SolveResult last;
  double cpu = 0.0;
  int factorizations = 0;
  for (auto _ : state) {
    last = SolveResult{};  // the previous solve's memory freed outside the timing
    const double before = cpu_seconds();
    last = solve_problem(valve_case().problem, options);
    cpu += cpu_seconds() - before;
    factorizations += last.solver->factorizations();
    benchmark::DoNotOptimize(last.results.gaps.data());
  }
  set_counters(state, *last.solver, cpu, factorizations);
  state.counters["newton"] = last.solution.newton.iterations;
  state.counters["lambda_uWb"] = last.solution.flux_linkage[0] * 1e6;
  state.counters["dlambda_dI_uH"] = last.solution.incremental_inductance[0] * 1e6;
}
BENCHMARK(BM_AnnularValveFineSolveProblem)
    ->ArgsProduct({{8, 16}, {0, 1}})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// Nonlinear solve at 1 A from A = 0 (with dlambda/dI) on the default mesh; setup excluded.
void BM_AnnularValveNonlinearSolve(benchmark::State& state) {
  SolveResult setup = solve_problem(valve_case().problem);
  MagnetostaticSolver& solver = *setup.solver;
  int iterations = 0, factorizations = 0;
  double cpu = 0.0;
  for (auto _ : state) {
    const int factorized = solver.factorizations();
    const double before = cpu_seconds();
    const Solution s = solver.solve();
    cpu += cpu_seconds() - before;
    factorizations += solver.factorizations() - factorized;
    iterations = s.newton.iterations;
    benchmark::DoNotOptimize(s.flux_linkage.data());
  }
  set_counters(state, solver, cpu, factorizations);
  state.counters["newton"] = iterations;
}
BENCHMARK(BM_AnnularValveNonlinearSolve)->Unit(benchmark::kMillisecond)->UseRealTime();

/// 21-point sweep 0..2 A in 0.1 A steps (lambda, L, dlambda/dI per point), warm-started.
void BM_AnnularValveSweep21(benchmark::State& state) {
  SolveResult setup = solve_problem(valve_case().problem);
  MagnetostaticSolver& solver = *setup.solver;
  std::vector<double> currents;
  for (int k = 0; k <= 20; ++k) currents.push_back(0.1 * k);
  int newton = 0, factorizations = 0;
  double cpu = 0.0;
  for (auto _ : state) {
    const int factorized = solver.factorizations();
    const double before = cpu_seconds();
    const std::vector<SweepPoint> table = solver.sweep(0, currents);
    cpu += cpu_seconds() - before;
    factorizations += solver.factorizations() - factorized;
    newton = 0;
    for (const SweepPoint& p : table) newton += p.newton_iterations;
    benchmark::DoNotOptimize(table.data());
  }
  set_counters(state, solver, cpu, factorizations);
  state.counters["newton"] = newton;
}
BENCHMARK(BM_AnnularValveSweep21)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
