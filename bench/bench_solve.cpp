// Benchmarks of the magnetostatic solver: nonlinear solve time against the number of unknowns,
// and a 21-point current sweep reusing the factorisation analysis. Model: the axisymmetric
// AISI 1010 pot core with a 1 mm air gap of tests/magnetostatics/pot_core.hpp (400 turns),
// structured P2 meshes refined uniformly.

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cstdlib>
#include <limits>
#include <string>

#include "magnetostatics/nested_solve.hpp"
#include "magnetostatics/serial_openmp.hpp"
#include "magnetostatics/solver.hpp"
#include "tests/magnetostatics/pot_core.hpp"
#include "tests/magnetostatics/steel.hpp"

namespace {

using namespace rheomag;
using namespace rheomag::magnetostatics;
using namespace rheomag::cases;

/// Cells per millimetre giving about `dofs` P2 unknowns on the pot core (2400 p^2).
double cells_per_mm(double dofs) {
  return std::sqrt(dofs / 2400.0);
}

/// User + system CPU time of the whole process [s].
double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

/// Times `solve` (a nonlinear solve at 2 A from A = 0 and dlambda/dI, given a freshly built
/// solver on the about `state.range(0)`-unknown pot-core mesh; setup excluded) and reports
/// the solver's counters.
template <class Solve>
void time_solves(benchmark::State& state, const SolveOptions& options, Solve solve) {
  const test::PotCore core;
  const Material steel = test::aisi1010();
  if (steel.bh.empty()) {
    state.SkipWithError("AISI 1010 B-H table not found");
    return;
  }
  const Problem problem = test::pot_core_problem(steel, 400, 2.0, 2);
  const mesh::Mesh mesh = test::pot_core_mesh(core, cells_per_mm(state.range(0)), 2);
  int iterations = 0, local_steps = 0, factorizations = 0, cg = 0, dofs = 0;
  double cpu = 0.0, lambda = 0.0, inductance = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    MagnetostaticSolver solver(problem, mesh, options);
    state.ResumeTiming();
    const double cpu_start = process_cpu_seconds();
    const Solution s = solve(solver);
    cpu += process_cpu_seconds() - cpu_start;
    iterations = s.newton.iterations;
    local_steps = s.newton.local_steps;
    factorizations = solver.factorizations();
    cg = solver.reuse_iterations();
    dofs = solver.dofs().free_count();
    lambda = s.flux_linkage[0];
    inductance = s.incremental_inductance[0];
  }
  state.counters["cpu_s"] = cpu / static_cast<double>(state.iterations());
  state.counters["dofs"] = dofs;
  state.counters["newton"] = iterations;
  state.counters["local_steps"] = local_steps;
  state.counters["factorisations"] = factorizations;
  state.counters["cg_iterations"] = cg;
  state.counters["lambda_uWb"] = lambda * 1e6;
  state.counters["dlambda_dI_uH"] = inductance * 1e6;
}

/// Nonlinear solve at 2 A (B_gap ~ 1 T) from A = 0, then dlambda/dI at the solution (as the CLI
/// does); setup (mesh, pattern, symbolic analysis) excluded. Each timed solve starts from a
/// fresh solver state (no factorisation kept from an earlier solve), as a first `rheomag solve`.
void BM_NonlinearSolve(benchmark::State& state) {
  time_solves(state, {}, [](MagnetostaticSolver& solver) { return solver.solve(); });
}
BENCHMARK(BM_NonlinearSolve)
    ->Arg(10'000)
    ->Arg(30'000)
    ->Arg(100'000)
    ->Arg(300'000)
    ->Arg(1'000'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// The same solve by nested iteration (nested_solve.hpp): the pot core solved on meshes with
/// half, a quarter, ... the cells per millimetre (down to about 1.5e4 unknowns, coarsest first,
/// their setup timed), each interpolated onto the next, Newton on the fine mesh last. Second
/// argument: the most CG iterations with an old factorisation (0: the default reuse rule; else
/// also no refactorisation on a changed tangent while CG converges, FactorReuse). Third: 1 for
/// Newton's default oversolving guard, 0 without it (NewtonOptions::oversolve_guard = 0, the
/// solver before the guard), side by side.
void BM_NestedSolve(benchmark::State& state) {
  const test::PotCore core;
  std::vector<mesh::Mesh> coarser;
  for (double dofs = state.range(0) / 4.0; dofs >= 1.5e4; dofs /= 4.0) {
    coarser.insert(coarser.begin(), test::pot_core_mesh(core, cells_per_mm(dofs), 2));
  }
  SolveOptions options;
  if (state.range(2) == 0) options.newton.oversolve_guard = 0.0;
  if (state.range(1) > 0) {
    options.reuse.refactor_change = std::numeric_limits<double>::infinity();
    options.reuse.max_iterations = static_cast<int>(state.range(1));
  }
  time_solves(state, options, [&](MagnetostaticSolver& solver) {
    std::vector<double> currents{solver.problem().circuits[0].current};
    return solve_nested(solver, coarser, currents);
  });
  state.counters["levels"] = static_cast<double>(coarser.size() + 1);
}
BENCHMARK(BM_NestedSolve)
    ->ArgsProduct({{10'000, 100'000, 1'000'000}, {0, 30}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// Setup cost on the same meshes: dof map, sparsity pattern, scatter map, symbolic analysis.
void BM_SolverSetup(benchmark::State& state) {
  const test::PotCore core;
  const Material steel = test::aisi1010();
  const mesh::Mesh m = test::pot_core_mesh(core, cells_per_mm(state.range(0)), 2);
  for (auto _ : state) {
    MagnetostaticSolver solver(test::pot_core_problem(steel, 400, 2.0, 2), m);
    benchmark::DoNotOptimize(solver.dofs().free_count());
  }
}
BENCHMARK(BM_SolverSetup)->Arg(100'000)->Unit(benchmark::kMillisecond)->UseRealTime();

/// One global assembly at the 2 A solution: residual only (argument 0) or residual and tangent
/// (argument 1), on the about 1e5-unknown mesh. Newton does one tangent assembly per step and one
/// residual assembly per line-search trial.
void BM_Assembly(benchmark::State& state) {
  const test::PotCore core;
  MagnetostaticSolver solver(test::pot_core_problem(test::aisi1010(), 400, 2.0, 2),
                             test::pot_core_mesh(core, cells_per_mm(100'000), 2));
  const Solution solution = solver.solve();
  SparseMatrix tangent = solver.assembler().pattern();
  Eigen::VectorXd residual;
  for (auto _ : state) {
    solver.assembler().assemble(solution.a, residual, state.range(0) ? &tangent : nullptr);
    benchmark::DoNotOptimize(residual.data());
  }
  state.counters["elements"] = static_cast<double>(solver.mesh().triangles.size());
}
BENCHMARK(BM_Assembly)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

/// CHOLMOD on the tangent at the 2 A solution of the about 1e5-unknown mesh: numeric supernodal
/// factorisation (argument 0; the symbolic analysis is done once outside the loop) or one
/// forward/back substitution with that factor (argument 1), as one preconditioned CG iteration
/// costs. Counters: nonzeros of L and flops of the factorisation as CHOLMOD reports them.
void BM_Cholesky(benchmark::State& state) {
  const test::PotCore core;
  MagnetostaticSolver solver(test::pot_core_problem(test::aisi1010(), 400, 2.0, 2),
                             test::pot_core_mesh(core, cells_per_mm(100'000), 2));
  const SparseMatrix tangent = solver.tangent(solver.solve().a);
  const SerialOpenMp serial;  // as the solver runs CHOLMOD
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> cholesky;
  cholesky.analyzePattern(tangent);
  cholesky.factorize(tangent);
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(tangent.rows());
  for (auto _ : state) {
    if (state.range(0) == 0) {
      cholesky.factorize(tangent);
    } else {
      Eigen::VectorXd x = cholesky.solve(rhs);
      benchmark::DoNotOptimize(x.data());
    }
  }
  state.counters["lnz"] = cholesky.cholmod().lnz;
  state.counters["flops"] = cholesky.cholmod().fl;
}
BENCHMARK(BM_Cholesky)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

/// 21-point sweep 0..4 A (lambda(I), L(I), dlambda/dI), warm-started, one symbolic analysis.
void BM_CurrentSweep21(benchmark::State& state) {
  const test::PotCore core;
  MagnetostaticSolver solver(test::pot_core_problem(test::aisi1010(), 400, 0.0, 2),
                             test::pot_core_mesh(core, cells_per_mm(state.range(0)), 2));
  std::vector<double> currents;
  for (int k = 0; k <= 20; ++k) currents.push_back(0.2 * k);
  int factorizations = 0;
  for (auto _ : state) {
    const int before = solver.factorizations();
    const auto table = solver.sweep(0, currents);
    factorizations = solver.factorizations() - before;
    benchmark::DoNotOptimize(table.data());
  }
  state.counters["dofs"] = solver.dofs().free_count();
  state.counters["factorisations"] = factorizations;
}
BENCHMARK(BM_CurrentSweep21)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
