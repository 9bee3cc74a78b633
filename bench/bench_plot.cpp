// What drawing adds to a solve of the reference valve (cases/annular_valve.toml at 1 A, P2,
// default mesh): the mesh + solve + results (what `rheomag solve` computes), then the field map
// drawn and encoded as PNG and as SVG, and the gap profile plot (issue 29: drawing must add
// under 1 s). Numbers in docs/plots.md.

#include <benchmark/benchmark.h>

#include <string>

#include "case/case_file.hpp"
#include "figures/field_map.hpp"
#include "figures/gap_profile.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "optimise/spec.hpp"
#include "valve/valve_options.hpp"

namespace {

using namespace rheomag;

cases::Case reference_valve() {
  return cases::read_case_file(std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml");
}

void BM_SolveReferenceValve(benchmark::State& state) {
  const cases::Case c = reference_valve();
  for (auto _ : state) benchmark::DoNotOptimize(magnetostatics::solve_problem(c.problem));
}
BENCHMARK(BM_SolveReferenceValve)->Unit(benchmark::kMillisecond);

/// Field map drawn (recording) and encoded: state.range(0) 0 = PNG, 1 = SVG.
void BM_FieldMapReferenceValve(benchmark::State& state) {
  const cases::Case c = reference_valve();
  const magnetostatics::SolveResult solved = magnetostatics::solve_problem(c.problem);
  for (auto _ : state) {
    const figures::FieldMap map =
        figures::draw_field_map(*solved.solver, solved.solution, solved.results, {});
    benchmark::DoNotOptimize(state.range(0) == 0 ? map.figure.png() : map.figure.svg());
  }
}
BENCHMARK(BM_FieldMapReferenceValve)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_GapProfilePng(benchmark::State& state) {
  const cases::Case c = reference_valve();
  const magnetostatics::SolveResult solved = magnetostatics::solve_problem(c.problem);
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        figures::gap_profile_figure(solved.results.gaps.front(), 900, 560).png());
  }
}
BENCHMARK(BM_GapProfilePng)->Unit(benchmark::kMillisecond);

}  // namespace
