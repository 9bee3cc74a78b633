// Ipopt wiring on problems with known optima.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "optimise/ipopt.hpp"
#include "optimise_fixture.hpp"

namespace {

using rheomag::optimise::NlpProblem;
using rheomag::optimise::solve_nlp;

// Analytic magnetic-circuit valve (optimise_fixture.hpp), with its iterations reported as
// progress: dp = gain N L, the envelope
// 2 L + a N <= L_max (a = axial winding length per turn). Lagrange: the optimum shares the
// length equally, 2 L* = a N* = L_max / 2, i.e. L* = L_max / 4, N* = L_max / (2 a).
TEST(OptimiseIpopt, MagneticCircuitValveReachesTheAnalyticOptimum) {
  const optimise_fixture::MagneticCircuitValve model;
  const double l_max = model.l_max, a = model.a, gain = model.gain();
  const double l_star = l_max / 4.0, n_star = l_max / (2.0 * a);
  NlpProblem p;
  p.lower = {1e-3, 50.0};
  p.upper = {20e-3, 800.0};
  p.start = {5e-3, 200.0};
  p.g_lower = {-1e19};
  p.g_upper = {l_max};
  // Scaled as the FE driver does: f = -dp / dp_ref.
  const double dp_ref = gain * 5e-3 * 200.0;
  p.values = [&](const std::vector<double>& x, double& f, std::vector<double>& g) {
    f = -gain * x[0] * x[1] / dp_ref;
    g[0] = 2.0 * x[0] + a * x[1];
    return true;
  };
  p.derivatives = [&](const std::vector<double>& x, std::vector<double>& grad,
                      std::vector<double>& jac) {
    grad[0] = -gain * x[1] / dp_ref;
    grad[1] = -gain * x[0] / dp_ref;
    jac[0] = 2.0;
    jac[1] = a;
    return true;
  };
  // Progress: every iteration reported once, in order, from the starting point (0) to the last.
  rheomag::optimise::IpoptSettings settings;
  std::vector<int> reported;
  settings.on_iteration = [&](int iteration) { reported.push_back(iteration); };
  const auto r = solve_nlp(p, settings);
  ASSERT_TRUE(r.converged) << r.status;
  ASSERT_EQ(reported.size(), static_cast<std::size_t>(r.iterations) + 1);
  for (std::size_t k = 0; k < reported.size(); ++k) EXPECT_EQ(reported[k], static_cast<int>(k));
  // Tolerance: Ipopt tol 1e-8 on a well-scaled problem -> 1e-5 relative on the optimum.
  EXPECT_NEAR(r.x[0], l_star, 1e-5 * l_star);
  EXPECT_NEAR(r.x[1], n_star, 1e-5 * n_star);
  EXPECT_NEAR(-r.f * dp_ref, gain * l_star * n_star, 1e-6 * gain * l_star * n_star);
  EXPECT_GT(r.iterations, 0);
}

// Conflicting constraints x0 + x1 >= 3 and x0 + x1 <= 1 on [0, 1]^2: Ipopt must not report
// success.
TEST(OptimiseIpopt, ConflictingConstraintsAreNotReportedAsSolved) {
  NlpProblem p;
  p.lower = {0.0, 0.0};
  p.upper = {1.0, 1.0};
  p.start = {0.5, 0.5};
  p.g_lower = {3.0, -1e19};
  p.g_upper = {1e19, 1.0};
  p.values = [](const std::vector<double>& x, double& f, std::vector<double>& g) {
    f = (x[0] - 0.2) * (x[0] - 0.2) + x[1] * x[1];
    g[0] = x[0] + x[1];
    g[1] = x[0] + x[1];
    return true;
  };
  p.derivatives = [](const std::vector<double>& x, std::vector<double>& grad,
                     std::vector<double>& jac) {
    grad[0] = 2.0 * (x[0] - 0.2);
    grad[1] = 2.0 * x[1];
    jac = {1.0, 1.0, 1.0, 1.0};
    return true;
  };
  const auto r = solve_nlp(p);
  EXPECT_FALSE(r.converged) << r.status;
}

}  // namespace
