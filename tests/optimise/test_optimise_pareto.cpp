// Weighted-sum objectives and the epsilon-constraint Pareto front on the analytic
// magnetic-circuit valve (optimise_fixture.hpp), where both are known in closed form.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "optimise/continuous.hpp"
#include "optimise/pareto_front.hpp"
#include "optimise/problem.hpp"
#include "optimise/report.hpp"
#include "optimise_fixture.hpp"

namespace {

using namespace rheomag;
using optimise_fixture::MagneticCircuitValve;

// The single-objective optimiser over the analytic model, as the FE run plugs in its own.
struct AnalyticOptimiser {
  MagneticCircuitValve model;
  std::vector<optimise::HistoryRow> history;
  optimise::DesignReport operator()(const optimise::OptimiseSpec& spec,
                                    const std::vector<double>& start, double scale) {
    optimise::ScaledProgram program(
        spec, [this](const std::vector<double>& x, bool) { return model.quantities(x); }, scale,
        history);
    optimise::IpoptSettings settings;
    settings.tolerance = spec.tolerance;
    settings.max_iterations = spec.max_iterations;
    const auto solved = program.solve(start, settings);
    EXPECT_TRUE(solved.converged) << solved.status;
    auto report = optimise::report_design(spec, solved.x, model.quantities(solved.x));
    report.strict_vertex = optimise::is_strict_vertex(spec, solved);
    return report;
  }
};

// The front's optimiser: `optimiser`, its evaluations counted in `solves`.
optimise::OptimiseFrom counting(AnalyticOptimiser& optimiser, int& solves) {
  return [&optimiser, &solves](const optimise::OptimiseSpec& s, const std::vector<double>& start,
                               double scale) {
    const auto before = optimiser.history.size();
    auto r = optimiser(s, start, scale);
    solves += static_cast<int>(optimiser.history.size() - before);
    return r;
  };
}

// Weighted sum f = dp_on / dp_0 - w tau / tau_0 (each term normalised by its value at the start
// design x0 = (L0, N0), as run_optimisation does). On the envelope L = (L_max - a N) / 2,
// df/dN = 0 gives N* = (L_max - 2 w L0) / (2 a) (dp_0 = gain L0 N0, tau_0 = b N0): for w = 1,
// L0 = 5 mm: N* = 340, L* = 13.5 mm. Tolerance 1e-4 relative (Ipopt tol 1e-9, exact
// central differences on a bilinear model).
TEST(OptimisePareto, WeightedSumReachesTheAnalyticOptimum) {
  AnalyticOptimiser optimiser;
  const auto& m = optimiser.model;
  auto spec = m.spec();
  spec.variables[0].upper = 30e-3;
  const std::vector<double> x0 = {5e-3, 200.0};
  const auto q0 = m.quantities(x0);
  const double w = 1.0;
  spec.terms = {{design::Quantity::dp_on, 1.0, q0[design::Quantity::dp_on]},
                {design::Quantity::time_constant, -w, q0[design::Quantity::time_constant]}};
  spec.objective = "weighted_sum";
  const auto r = optimiser(spec, x0, 1.0);
  const double n_star = (m.l_max - 2.0 * w * x0[0]) / (2.0 * m.a);
  const double l_star = (m.l_max - m.a * n_star) / 2.0;
  EXPECT_NEAR(r.x[1], n_star, 1e-4 * n_star);
  EXPECT_NEAR(r.x[0], l_star, 1e-4 * l_star);
  const double f_star =
      m.gain() * l_star * n_star / q0[design::Quantity::dp_on] - w * n_star / x0[1];
  EXPECT_NEAR(r.objective, f_star, 1e-6 * std::abs(f_star));
}

// Front of max dp_on against min tau = b N within 2 L + a N <= L_max: at level eps the turns are
// limited to N = eps / b (below N* = L_max / (2 a)), L = (L_max - a N) / 2, so
// dp(eps) = gain N (L_max - a N) / 2. End points: the dp optimum (N* = 440, tau = 44 ms) and the
// tau optimum (N = 50, the bound: tau = 5 ms). Checked: every level within 1e-4 of dp(eps), the
// front monotone (dp falls as eps tightens), the end points equal the single-objective optima.
TEST(OptimisePareto, EpsilonConstraintFrontMatchesTheAnalyticFront) {
  AnalyticOptimiser optimiser;
  const auto& m = optimiser.model;
  auto spec = m.spec();
  spec.variables[0].upper = 30e-3;
  spec.pareto = optimise::ParetoSpec{design::Quantity::time_constant, false, 6};
  const std::vector<double> x0 = {5e-3, 200.0};
  const auto alone = optimiser(spec, x0, std::abs(m.quantities(x0)[design::Quantity::dp_on]));
  const double n_star = m.l_max / (2.0 * m.a);
  ASSERT_NEAR(alone.x[1], n_star, 1e-4 * n_star);

  int solves = 0;
  const optimise::OptimiseFrom from = counting(optimiser, solves);
  const auto front = optimise::pareto_front(spec, alone, from, [&] { return solves; });
  ASSERT_EQ(front.points.size(), 6u);
  const double tau_min = m.b * spec.variables[1].lower;
  EXPECT_NEAR(front.second_alone.quantities[design::Quantity::time_constant], tau_min,
              1e-4 * tau_min);
  EXPECT_NEAR(front.points.front().epsilon, m.b * n_star, 1e-4 * m.b * n_star);
  EXPECT_NEAR(front.points.back().epsilon, tau_min, 1e-4 * tau_min);
  for (std::size_t k = 0; k < front.points.size(); ++k) {
    const auto& p = front.points[k];
    const double n = std::min(p.epsilon / m.b, n_star);
    const double dp = m.gain() * n * (m.l_max - m.a * n) / 2.0;
    EXPECT_TRUE(p.design.feasible) << k;
    EXPECT_NEAR(p.design.objective, dp, 1e-4 * dp) << "level " << k;
    EXPECT_LE(p.design.quantities[design::Quantity::time_constant], p.epsilon * (1.0 + 1e-6)) << k;
    if (k > 0) {
      EXPECT_LT(p.design.objective, front.points[k - 1].design.objective) << k;
      EXPECT_GT(p.fe_solves, 0) << k;
    }
  }
  // End points: the objective's own optimum and, at the last level, the turns at their bound.
  // tau does not depend on L, so the tau optimum is no strict vertex and the last level is
  // optimised (its L on the envelope: dp within 1e-4 above).
  EXPECT_FALSE(front.second_alone.strict_vertex);
  EXPECT_DOUBLE_EQ(front.points.front().design.objective, alone.objective);
  EXPECT_NEAR(front.points.back().design.x[1], spec.variables[1].lower, 1e-4 * 50.0);
  const std::string csv = optimise::pareto_csv(spec, front);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 7);  // header + 6 levels
}

// Front of max dp_on against min length = 2 L + a N. The length optimum is the box's vertex
// (L, N) = (1 mm, 50): both bounds pressed on (length grows with each), so no other design has
// its length and it is the last level as found, with no optimisation (0 solves), its dp
// gain L N exactly. A middle level eps: max gain L N with 2 L + a N <= eps gives L = eps / 4,
// N = eps / (2 a), dp = gain eps^2 / (8 a) (within 1e-4).
TEST(OptimisePareto, LastLevelAtAStrictVertexIsTheSecondOptimumItself) {
  AnalyticOptimiser optimiser;
  const auto& m = optimiser.model;
  auto spec = m.spec();
  spec.pareto = optimise::ParetoSpec{design::Quantity::length, false, 3};
  const std::vector<double> x0 = {5e-3, 200.0};
  const auto alone = optimiser(spec, x0, std::abs(m.quantities(x0)[design::Quantity::dp_on]));
  int solves = 0;
  const optimise::OptimiseFrom from = counting(optimiser, solves);
  const auto front = optimise::pareto_front(spec, alone, from, [&] { return solves; });
  ASSERT_EQ(front.points.size(), 3u);
  EXPECT_TRUE(front.second_alone.strict_vertex);
  const auto& last = front.points.back();
  EXPECT_TRUE(last.design.strict_vertex);
  EXPECT_EQ(last.fe_solves, 0);
  EXPECT_EQ(last.design.x, front.second_alone.x);
  const double dp_vertex = m.gain() * 1e-3 * 50.0;
  EXPECT_NEAR(last.design.objective, dp_vertex, 1e-6 * dp_vertex);  // reported for dp_on
  EXPECT_TRUE(last.design.feasible);
  const double eps = front.points[1].epsilon;
  const double dp_middle = m.gain() * eps * eps / (8.0 * m.a);
  EXPECT_NEAR(front.points[1].design.objective, dp_middle, 1e-4 * dp_middle);
  EXPECT_GT(front.points[1].fe_solves, 0);
}

}  // namespace
