// Benchmarks of the transient solver on the annular reference valve (cases/annular_valve.toml,
// paper 000): the 0.5 s response to a voltage step at the default mesh with adaptive steps
// (target < 5 s wall), and the cost against the number of dofs (element order 1 / 2, 8 instead of 4
// elements across the gaps) and of equal steps; the quasi-static reduction of the same step.
// Counters: dofs, steps, Newton iterations, factorisations (the reduction: its table's size).

#include <benchmark/benchmark.h>

#include <cstddef>
#include <memory>

#include "case/case_file.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "transient/quasi_static.hpp"
#include "transient/transient_solver.hpp"
#include "valve/valve_chain.hpp"  // registers the case's [valve] section

namespace {

using namespace rheomag;

const cases::Case& valve_case() {
  static const cases::Case c = cases::load_case(RHEOMAG_SOURCE_DIR "/cases/annular_valve.toml");
  return c;
}

/// The valve's voltage step: 4.8 V on its ~4.8 Ohm winding (about 1 A, the paper's current).
transient::TransientOptions voltage_step(int steps) {
  transient::TransientOptions o;
  o.drive = transient::Drive::voltage;
  o.value = 4.8;
  o.resistance = 4.8;
  o.duration = 0.5;
  o.steps = steps;
  return o;
}

/// One run per iteration on a solver built once (meshing and setup excluded).
void run(benchmark::State& state, int order, int gap_elements, int steps) {
  cases::Problem problem = valve_case().problem;
  problem.order = order;
  problem.min_gap_elements = gap_elements;
  auto statics = magnetostatics::make_solver(problem);
  transient::TransientSolver solver(*statics, transient::eddy_coefficients(statics->problem(), {}));
  transient::TransientResult last;
  for (auto _ : state) last = solver.run(voltage_step(steps));
  state.counters["dofs"] = last.dofs;
  state.counters["steps"] = last.steps;
  state.counters["newton"] = last.newton_iterations;
  state.counters["factorisations"] = last.factorizations;
  state.counters["t90_ms"] = last.t90 ? *last.t90 * 1e3 : -1.0;
}

void BM_AnnularValveVoltageStep(benchmark::State& state) {
  run(state, 2, 4, 0);
}
void BM_AnnularValveOrder1(benchmark::State& state) {
  run(state, 1, 4, 0);
}
void BM_AnnularValveRefined(benchmark::State& state) {
  run(state, 2, 8, 0);
}
void BM_AnnularValveEqualSteps(benchmark::State& state) {
  run(state, 2, 4, static_cast<int>(state.range(0)));
}

/// The reference valve's transient solver, built once, and its 4.8 V step's final current.
struct ValveReduction {
  std::unique_ptr<magnetostatics::MagnetostaticSolver> statics =
      magnetostatics::make_solver(valve_case().problem);
  transient::TransientSolver solver{*statics, transient::eddy_coefficients(statics->problem(), {})};
  transient::TransientOptions step = voltage_step(0);
  double final_current = step.value / step.resistance;
};

/// The quasi-static reduction of the same step (transient/quasi_static.hpp): its table of
/// static solves from 0 to V / R and the step's rise times, on a solver built once.
void BM_AnnularValveQuasiStatic(benchmark::State& state) {
  ValveReduction v;
  transient::QuasiStaticTable table;
  transient::QuasiStaticStep step;
  for (auto _ : state) {
    table = transient::quasi_static_table(v.solver, 0.0, v.final_current, 8);
    step = transient::quasi_static_step(table, 0.0, v.final_current, v.step.resistance);
  }
  state.counters["table"] = static_cast<double>(table.points.size());
  state.counters["newton"] = table.newton_iterations;
  state.counters["t90_ms"] = step.t90 ? *step.t90 * 1e3 : -1.0;
}

// An optimiser's finite-difference neighbour: the table over a range 0.1 % wider (a design whose
// V / R moved), cold (/0), on the centre's grid from its states (/1,
// transient::QuasiStaticReuse) or linearised about them (/2, QuasiStaticReuse::linearise).
void BM_AnnularValveQuasiStaticNeighbour(benchmark::State& state) {
  ValveReduction v;
  transient::QuasiStaticStart centre;
  transient::quasi_static_table(v.solver, 0.0, v.final_current, 8,
                                {.keep = &centre, .keep_factor_bytes = std::size_t{1} << 30});
  transient::QuasiStaticReuse reuse;
  if (state.range(0) >= 1)
    reuse = {.start = &centre, .fixed_grid = true, .linearise = state.range(0) == 2};
  transient::QuasiStaticTable table;
  for (auto _ : state)
    table = transient::quasi_static_table(v.solver, 0.0, 1.001 * v.final_current, 8, reuse);
  state.counters["table"] = static_cast<double>(table.points.size());
  state.counters["newton"] = table.newton_iterations;
  state.counters["linearised"] = table.linearised;
  double factor_bytes = 0.0;  // the centre's kept factorisations
  for (const auto& factor : centre.factors)
    if (factor) factor_bytes += static_cast<double>(factor->bytes());
  state.counters["factors_MB"] = factor_bytes / 1e6;
}

BENCHMARK(BM_AnnularValveVoltageStep)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_AnnularValveQuasiStatic)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_AnnularValveQuasiStaticNeighbour)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kSecond)
    ->Iterations(3);
BENCHMARK(BM_AnnularValveOrder1)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_AnnularValveRefined)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_AnnularValveEqualSteps)
    ->Arg(25)
    ->Arg(50)
    ->Arg(100)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
