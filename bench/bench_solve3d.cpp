// Benchmarks of the 3D solver (rheomag solve --3d): the bundled annular valve revolved (wedge
// model, default mesh: 1 % agreement with 2D), the small test valve with a lead slot (half
// model, coarse mesh) and the bundled annular valve with a lead slot on the swept mesh (half
// model, swept_options(), docs/magnetostatics3d.md: six ways of starting and solving Newton's
// steps side by side, CHOLMOD and AMS, BM_AnnularValveLeadSlotHalfSwept/0 the previous solver).
// Whole pipeline timed: revolve, TetGen, gauge, loads, Newton, results. Peak memory: the
// lead-slot model's max_rss_MB (process-wide) or /usr/bin/time -v. BM_Team20Fine: TEAM problem 20
// on the 2.5 mm grid at the four measured excitations, with the pole force per excitation as
// counters (F980 ... F5020 [N]; measured 8.0, 53.8, 74.7, 79.7 N).

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "case/case_file.hpp"
#include "case/toml_section.hpp"
#include "magnetostatics3d/solve3d.hpp"
#include "magnetostatics3d/team20.hpp"
#include "valve/valve_chain.hpp"  // registers the bundled cases' [valve] section

namespace {

using namespace rheomag;
using namespace rheomag::magnetostatics3d;

void report(benchmark::State& state, const Solve3dResult& s) {
  state.counters["tetrahedra"] = s.results.tetrahedra;
  state.counters["dofs"] = s.results.dofs;
  state.counters["newton"] = s.results.newton_iterations;
  state.counters["mesh_s"] = s.mesh_seconds;
}

void BM_AnnularValveWedge(benchmark::State& state) {
  const cases::Case c =
      cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml");
  for (auto _ : state) {
    const Solve3dResult s = solve_problem_3d(c.problem);
    report(state, s);
  }
}
BENCHMARK(BM_AnnularValveWedge)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

void BM_SmallValveLeadSlotHalf(benchmark::State& state) {
  const std::string path =
      std::string(RHEOMAG_SOURCE_DIR) + "/tests/data/magnetostatics3d/small_valve.toml";
  const cases::Case c = cases::parse_case(
      cases::read_input_file(path) +
          "\n[[feature]]\nkind = \"lead_slot\"\nregion = \"core\"\nwidth = 2.0\ndepth = 1.5\n",
      path);
  Solve3dOptions options;
  options.gap_layers = 1;
  options.region_fraction = 0.5;
  options.facet_angle = 10.0 * 3.14159265358979323846 / 180.0;
  for (auto _ : state) {
    const Solve3dResult s = solve_problem_3d(c.problem, read_features(c), options);
    report(state, s);
  }
}
BENCHMARK(BM_SmallValveLeadSlotHalf)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

/// How the lead-slot half model's Newton iteration is started and its steps solved.
struct Variant {
  bool warm_start;  // from the revolved 2D solution (else A = 0)
  bool reuse;       // CG on the last factorisation (Solve3dOptions' budget; else one per step)
  LinearSolver3d linear;  // CHOLMOD on the gauged system or AMS-preconditioned CG on all edges
  double ams_forcing;     // AMS: Newton's largest forcing term (Solve3dOptions::ams_max_forcing)
  bool guard = true;      // Newton's oversolving guard (NewtonOptions::oversolve_guard; else 0)
  bool local = false;     // local Newton corrections where the residual concentrates
  int ams_seeds = 0;      // AMS: seed edges of the corrections (0: Solve3dOptions' default)
  double ams_fraction = 0.0;  // AMS: their share of |R|^2 (0: Solve3dOptions' default)
};
constexpr Variant kVariants[] = {{false, false, LinearSolver3d::cholmod, 0.0},
                                 {false, true, LinearSolver3d::cholmod, 0.0},
                                 {true, false, LinearSolver3d::cholmod, 0.0},
                                 {true, true, LinearSolver3d::cholmod, 0.0},
                                 {false, false, LinearSolver3d::ams, 0.1},
                                 {false, false, LinearSolver3d::ams, 0.01},
                                 {false, false, LinearSolver3d::ams, 0.1, false},
                                 {true, true, LinearSolver3d::cholmod, 0.0, true, true},
                                 {true, false, LinearSolver3d::ams, 0.01, true, true},
                                 {true, false, LinearSolver3d::ams, 0.1, true, true, 500, 0.9}};

// The variants side by side in one process: /0 is the first solver (from A = 0, one
// factorisation per Newton step), /1 the default before local corrections, /4 and /5 AMS (one
// set-up per Newton step, forcing 0.1 and 0.01), /6 AMS at 0.1 without Newton's oversolving guard
// (the solver before it); /7 and /8 today's defaults with CHOLMOD and AMS (2D start, local
// corrections; the others have none), /9 the AMS default of session 48 (forcing 0.1, 500 seed
// edges holding 90 % of |R|^2); max_sector_change is the largest relative change of a gap's
// 10-degree sector average from /0 (or from the first variant run), flux_change that of lambda.
void BM_AnnularValveLeadSlotHalfSwept(benchmark::State& state) {
  static Results3d previous;
  const std::string path = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";
  const cases::Case c = cases::parse_case(
      cases::read_input_file(path) +
          "\n[[feature]]\nkind = \"lead_slot\"\nregion = \"core\"\nwidth = 3.0\ndepth = 2.0\n",
      path);
  const Variant v = kVariants[state.range(0)];
  Solve3dOptions options = swept_options();
  options.warm_start = v.warm_start;
  if (!v.reuse) options.reuse_iterations = 0;
  options.linear = v.linear;
  if (v.linear == LinearSolver3d::ams) options.ams_max_forcing = v.ams_forcing;
  if (v.ams_seeds > 0) options.ams_local_max_dofs = v.ams_seeds;
  if (v.ams_fraction > 0.0) options.ams_local_fraction = v.ams_fraction;
  if (!v.guard) options.newton.oversolve_guard = 0.0;
  if (!v.local) options.newton.local_iterations = 0;
  for (auto _ : state) {
    const Solve3dResult s = solve_problem_3d(c.problem, read_features(c), options);
    report(state, s);
    state.counters["local_steps"] = s.solution.newton.local_steps;
    state.counters["factorizations"] = s.results.factorizations;
    state.counters["cg"] = s.results.cg_iterations;
    if (state.range(0) == 0 || previous.circuits.empty()) previous = s.results;  // reference
    double change = 0.0;
    for (std::size_t g = 0; g < previous.gaps.size(); ++g)
      for (int k = 0; k < kThetaSectors; ++k)
        change = std::max(
            change,
            std::abs(s.results.gaps[g].b_avg_theta[k] / previous.gaps[g].b_avg_theta[k] - 1.0));
    state.counters["max_sector_change"] = change;
    state.counters["flux_change"] =
        s.results.circuits[0].flux_linkage / previous.circuits[0].flux_linkage - 1.0;
    // Process-wide peak so far (getrusage): a variant's own only when it runs first or alone
    // (--benchmark_filter=LeadSlotHalfSwept/4); else /usr/bin/time -v rheomag solve per setting.
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    state.counters["max_rss_MB"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
  }
  const std::string steps = v.linear == LinearSolver3d::ams
                                ? "AMS-CG, forcing " + std::to_string(v.ams_forcing).substr(0, 4)
                                : (v.reuse ? "CG on reused factor" : "factor per step");
  state.SetLabel(std::string(v.warm_start ? "2D start" : "A = 0") + ", " + steps +
                 (v.guard ? "" : ", no oversolving guard") +
                 (v.local ? ", local corrections" : ""));
}
BENCHMARK(BM_AnnularValveLeadSlotHalfSwept)
    ->DenseRange(0, 9)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

void BM_Team20Fine(benchmark::State& state) {
  Team20Options options;
  options.step = 2.5e-3;
  for (auto _ : state) {
    const std::vector<Team20Result> r = solve_team20({980, 3010, 4520, 5020}, options);
    state.counters["tetrahedra"] = static_cast<double>(r.back().tetrahedra);
    state.counters["dofs"] = r.back().dofs;
    int newton = 0;
    for (const Team20Result& x : r) {
      newton += x.newton_iterations;
      state.counters["F" + std::to_string(static_cast<int>(x.ampere_turns))] = -x.force_z;
    }
    state.counters["newton"] = newton;
  }
}
BENCHMARK(BM_Team20Fine)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
