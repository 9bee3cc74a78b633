// The optimiser's finite differences ([optimise] differences = "central" or "forward") on an
// analytic objective whose optimum and difference errors are known in closed form.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "optimise/problem.hpp"
#include "optimise_fixture.hpp"

namespace {

using namespace rheomag;

// dp_on = exp(-(x0 - 0.3)^2 - 2 (x1 - 1.2)^2) over x0 in [0, 1], x1 in [0, 2]: maximum at
// (0.3, 1.2), inside the bounds.
design::Quantities bump(const std::vector<double>& x) {
  design::Quantities q;
  q[design::Quantity::dp_on] =
      std::exp(-(x[0] - 0.3) * (x[0] - 0.3) - 2.0 * (x[1] - 1.2) * (x[1] - 1.2));
  return q;
}

optimise::OptimiseSpec bump_spec(optimise::Differences differences) {
  optimise::OptimiseSpec s;
  s.variables = {{"a", {}, 0.0, 1.0, 0.6}, {"b", {}, 0.0, 2.0, 0.5}};
  s.terms = {{design::Quantity::dp_on, 1.0, 1.0}};
  s.tolerance = 1e-10;
  s.max_iterations = 100;
  s.differences = differences;
  return s;
}

// One evaluation as the program asked for it.
struct Call {
  std::vector<double> x;
  bool neighbour;
};

// Every "gradient" row of `history` is a neighbour of the last other row: it differs from it
// in one coordinate by `step` of that variable's range, in the sense `forward` allows (+ away
// from the upper bound, - at it) or either for central. Returns the number of such rows.
int check_neighbours(const optimise::OptimiseSpec& spec,
                     const std::vector<optimise::HistoryRow>& history, bool forward) {
  const std::vector<double>* centre = nullptr;
  int rows = 0;
  for (const auto& row : history) {
    if (row.purpose != "gradient") {
      centre = &row.x;
      continue;
    }
    ++rows;
    EXPECT_NE(centre, nullptr);
    if (!centre) continue;
    int moved = 0;
    for (std::size_t i = 0; i < row.x.size(); ++i) {
      const auto& v = spec.variables[i];
      const double d = (row.x[i] - (*centre)[i]) / (v.upper - v.lower);
      if (std::abs(d) < 1e-14) continue;
      ++moved;
      EXPECT_NEAR(std::abs(d), spec.step, 1e-12);
      const bool at_upper = ((*centre)[i] - v.lower) / (v.upper - v.lower) + spec.step > 1.0;
      if (forward) {
        EXPECT_EQ(d > 0.0, !at_upper) << "variable " << i;
      }
    }
    EXPECT_EQ(moved, 1);
  }
  return rows;
}

// Central differences are exact to O(step^2) and find the maximum (to 1e-6; Ipopt tol 1e-10).
// Forward differences take half the neighbours; their O(step) error is h f''/2 in u, so the
// maximum they find is where f_u + (h/2) f_uu = 0: half a step below the true one in u
// (x0 = 0.3 - 0.5e-3, x1 = 1.2 - 0.5e-3 x 2), checked to 2 % of that shift.
TEST(OptimiseDifferences, ForwardTakesHalfTheNeighboursWithItsKnownFirstOrderError) {
  std::vector<int> neighbours, gradients;
  std::vector<std::vector<double>> optima;
  for (auto d : {optimise::Differences::central, optimise::Differences::forward}) {
    const auto spec = bump_spec(d);
    std::vector<optimise::HistoryRow> history;
    int derivative_calls = 0;
    optimise::ScaledProgram program(
        spec, [](const std::vector<double>& x, bool) { return bump(x); }, 1.0, history);
    optimise::IpoptSettings settings;
    settings.tolerance = spec.tolerance;
    settings.max_iterations = spec.max_iterations;
    // As the FE run does: the start's evaluation recorded before Ipopt runs.
    const std::vector<double> start = {0.6, 0.5};
    program.seed(start, bump(start), "initial");
    const auto solved = program.solve(start, settings);
    ASSERT_TRUE(solved.converged) << solved.status;
    optima.push_back(solved.x);
    neighbours.push_back(check_neighbours(spec, history, d == optimise::Differences::forward));
    // Distinct centres whose gradient was taken: the rows just before each run of gradients.
    for (std::size_t k = 1; k < history.size(); ++k)
      if (history[k].purpose == "gradient" && history[k - 1].purpose != "gradient")
        ++derivative_calls;
    gradients.push_back(derivative_calls);
  }
  const double h = bump_spec(optimise::Differences::central).step;
  EXPECT_NEAR(optima[0][0], 0.3, 1e-6);
  EXPECT_NEAR(optima[0][1], 1.2, 1e-6);
  EXPECT_NEAR(optima[1][0], 0.3 - 0.5 * h * 1.0, 0.02 * 0.5 * h);
  EXPECT_NEAR(optima[1][1], 1.2 - 0.5 * h * 2.0, 0.02 * 0.5 * h * 2.0);
  // Two neighbours per variable and gradient for central, one for forward.
  ASSERT_GT(gradients[0], 2);
  ASSERT_GT(gradients[1], 2);
  EXPECT_EQ(neighbours[0], 4 * gradients[0]);
  EXPECT_EQ(neighbours[1], 2 * gradients[1]);
}

// Forward differences subtract u's own evaluation, so the neighbours must reuse u's work: when
// another design was evaluated after u, u is evaluated again (purpose "centre", not a
// neighbour) before its neighbours. At the upper bound the difference is backward.
TEST(OptimiseDifferences, ForwardNeighboursFollowTheirOwnCentre) {
  const auto spec = bump_spec(optimise::Differences::forward);
  std::vector<optimise::HistoryRow> history;
  std::vector<Call> calls;
  optimise::ScaledProgram program(
      spec,
      [&](const std::vector<double>& x, bool neighbour) {
        calls.push_back({x, neighbour});
        return bump(x);
      },
      1.0, history);
  const std::vector<double> u1 = {0.4, 0.5}, u2 = {0.7, 0.2};
  double f = 0.0;
  std::vector<double> g, grad(2), jacobian;
  ASSERT_TRUE(program.values(u1, f, g));
  ASSERT_TRUE(program.values(u2, f, g));
  ASSERT_TRUE(program.derivatives(u1, grad, jacobian));
  ASSERT_EQ(calls.size(), 5u);
  const auto x1 = program.to_design(u1);
  EXPECT_EQ(calls[2].x, x1);
  EXPECT_FALSE(calls[2].neighbour);
  EXPECT_EQ(history[2].purpose, "centre");
  for (int k : {3, 4}) {
    EXPECT_TRUE(calls[k].neighbour);
    EXPECT_EQ(history[k].purpose, "gradient");
  }
  // The gradient of the scaled f = -dp_on to the forward difference's O(h) error.
  const double dp = bump(x1)[design::Quantity::dp_on], h = spec.step;
  EXPECT_NEAR(grad[0], 2.0 * (x1[0] - 0.3) * dp * 1.0, 2.0 * h * dp);
  EXPECT_NEAR(grad[1], 4.0 * (x1[1] - 1.2) * dp * 2.0, 10.0 * h * dp);
  // Asked again: everything cached, and u1 is now the last centre.
  ASSERT_TRUE(program.derivatives(u1, grad, jacobian));
  EXPECT_EQ(calls.size(), 5u);
  // At the upper bound of the first variable: u2's own evaluation is the last centre when it
  // was just evaluated, and the first neighbour lies below it.
  const std::vector<double> top = {1.0, 0.5};
  ASSERT_TRUE(program.values(top, f, g));
  ASSERT_TRUE(program.derivatives(top, grad, jacobian));
  ASSERT_EQ(calls.size(), 8u);
  EXPECT_LT(calls[6].x[0], 1.0);
  EXPECT_EQ(calls[7].x[1], program.to_design({1.0, 0.5 + h})[1]);
  EXPECT_EQ(check_neighbours(spec, history, true), 4);
}

// The fixture's two-variable [optimise] table with `line` added to it.
std::string with_line(const std::string& line) {
  std::string table = optimise_fixture::kTwoVariables;
  const std::string after = "max_iterations = 12\n";
  return table.insert(table.find(after) + after.size(), line + "\n");
}

// The key is read from the case and a value that is not a choice is refused, naming it.
TEST(OptimiseDifferences, ReadFromTheCaseAndUnknownValuesRefused) {
  const auto c = optimise_fixture::make_case(with_line("differences = \"forward\""));
  EXPECT_EQ(optimise::read_optimise_spec(c).differences, optimise::Differences::forward);
  EXPECT_EQ(optimise::read_optimise_spec(optimise_fixture::make_case(with_line(""))).differences,
            optimise::Differences::central);
  const std::string what = optimise_fixture::input_error(with_line("differences = \"backward\""));
  EXPECT_NE(what.find("differences"), std::string::npos) << what;
  EXPECT_NE(what.find("forward"), std::string::npos) << what;
  EXPECT_NE(what.find("coarse_annular.toml"), std::string::npos) << what;
}

}  // namespace
