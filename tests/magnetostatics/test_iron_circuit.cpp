// Iron pot core with an air gap: magnetic-circuit estimates and Newton convergence.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "magnetostatics/bh_curve.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"
#include "tests/magnetostatics/pot_core.hpp"
#include "tests/magnetostatics/steel.hpp"

namespace rheomag::magnetostatics {
namespace {

constexpr double kPi = std::numbers::pi;

/// B_z in the middle of the gap, 2.5 mm from the axis (2.5 gap widths from the post edge).
double gap_centre_b(const MagnetostaticSolver& solver, const Solution& s) {
  std::array<double, 2> b{};
  EXPECT_TRUE(flux_density_at(solver, s, {2.5e-3, 0.0}, test::kGap, b));
  return b[1];
}

TEST(IronCircuit, HighPermeabilityGapFieldIsMu0NIOverG) {
  // Reference: magnetic circuit with infinitely permeable iron, B_gap = mu0 N I / g (= 1.0053 T
  // for N I = 800 A, g = 1 mm). Valid in the gap away from its edge (fringing decays like
  // exp(-pi d / g) ~ 4e-4 at d = 2.5 g) and with mu_r = 1e5 the iron drop is ~ l_iron/(mu_r g)
  // ~ 1e-3. Tolerance 0.5 % at the gap centre; the gap-area average (edges included) within 5 %.
  const test::PotCore core;
  const cases::Problem problem =
      test::pot_core_problem({"iron", 1e5, {}, 0.0, "ideal"}, 400, 2.0, 2);
  MagnetostaticSolver solver(problem, test::pot_core_mesh(core, 2.0, 2));
  const Solution s = solver.solve();
  const double expected = kMu0 * 800.0 / core.gap;
  EXPECT_NEAR(gap_centre_b(solver, s), expected, 0.005 * expected);
  const Results res = compute_results(solver, s);
  ASSERT_EQ(res.gaps.size(), 1u);
  EXPECT_EQ(res.gaps[0].kind, mesh::GapKind::radial);
  EXPECT_NEAR(res.gaps[0].b_normal.average, expected, 0.05 * expected);
  EXPECT_LE(res.gaps[0].b_normal.average, 1.001 * expected);
  EXPECT_GT(res.gaps[0].line_samples, 100);
  EXPECT_NEAR(res.gaps[0].line_b.maximum, expected, 0.005 * expected);
  // Linear problem: Newton takes exactly one step to the tolerance.
  EXPECT_EQ(s.newton.iterations, 1);
  EXPECT_LT(s.newton.residual_history.back(), 1e-8);
}

/// Magnetic-circuit estimate with the iron MMF drop: flux Phi through the post (area pi a^2),
/// radially through the plates (area 2 pi r t) and the wall; solves
/// B g / mu0 + H(B) l_post + 2 integral H(Phi / (2 pi r t)) dr + H(B_wall) l_wall = N I.
double circuit_estimate(const test::PotCore& c, const BhCurve& iron, double ampere_turns) {
  const double t = c.outer_half - c.window_half;
  const double post_length = 2.0 * (c.window_half + 0.5 * t) - c.gap;
  const double wall_length = 2.0 * (c.window_half + 0.5 * t);
  const double wall_area = kPi * (c.wall_outer * c.wall_outer - c.wall_inner * c.wall_inner);
  const double r_from = 0.5 * c.post, r_to = 0.5 * (c.wall_inner + c.wall_outer);
  auto mmf = [&](double b) {
    const double flux = b * kPi * c.post * c.post;
    double plates = 0.0;
    const int n = 400;
    for (int k = 0; k < n; ++k) {
      const double r = r_from + (k + 0.5) * (r_to - r_from) / n;
      plates += iron.h(flux / (2 * kPi * r * t)) * (r_to - r_from) / n;
    }
    return b * c.gap / kMu0 + iron.h(b) * post_length + 2.0 * plates +
           iron.h(flux / wall_area) * wall_length;
  };
  double lo = 0.0, hi = 3.0;
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    (mmf(mid) < ampere_turns ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(IronCircuit, NonlinearIronMatchesMagneticCircuitAndNewtonIsQuadratic) {
  // Reference: circuit_estimate (iron drop ~ 2 % of N I at B_gap ~ 1 T, AISI 1010 unsaturated);
  // the estimate neglects fringing and leakage, valid at the gap centre: tolerance 1.5 %.
  // Newton: converges to 1e-8 in <= 12 steps, full steps at the end, and the terminal
  // convergence is quadratic: the order p = log(r_{k+1}/r_k) / log(r_k/r_{k-1}) of the last step
  // whose residual is above the round-off floor (1e-10) is >= 1.8 (measured values printed;
  // earlier steps are pre-asymptotic where |B| crosses B-H table intervals).
  const test::PotCore core;
  const cases::Material steel = test::aisi1010();
  const BhCurve curve(steel.bh, steel.name);
  const cases::Problem problem = test::pot_core_problem(steel, 400, 2.0, 2);
  MagnetostaticSolver solver(problem, test::pot_core_mesh(core, 2.0, 2));
  const Solution s = solver.solve();
  const double estimate = circuit_estimate(core, curve, 800.0);
  const double fe = gap_centre_b(solver, s);
  std::printf("B_gap FE %.5f T, circuit estimate %.5f T, mu0 NI/g %.5f T, Newton %d steps\n", fe,
              estimate, kMu0 * 800 / core.gap, s.newton.iterations);
  EXPECT_NEAR(fe, estimate, 0.015 * estimate);
  EXPECT_LT(estimate, kMu0 * 800 / core.gap);
  EXPECT_LE(s.newton.iterations, 12);
  EXPECT_GE(s.newton.iterations, 2);
  const auto& r = s.newton.residual_history;
  ASSERT_EQ(static_cast<int>(r.size()), s.newton.iterations + 1);
  EXPECT_LT(r.back(), 1e-8);
  double last_order = 0.0;
  for (std::size_t k = 0; k < r.size(); ++k) {
    std::printf("  Newton %zu: relative residual %.3e, step length %.3g\n", k, r[k],
                k ? s.newton.step_lengths[k - 1] : 0.0);
    if (k >= 1 && k + 1 < r.size() && r[k + 1] > 1e-10) {
      last_order = std::log(r[k + 1] / r[k]) / std::log(r[k] / r[k - 1]);
      std::printf("    convergence order %.2f\n", last_order);
    }
  }
  EXPECT_GE(last_order, 1.8);
  EXPECT_EQ(s.newton.step_lengths.back(), 1.0);
}

TEST(IronCircuit, SaturatedIronLimitsTheGapField) {
  // Reference: at N I = 2400 A the linear estimate mu0 N I / g = 3.0 T is impossible: the
  // AISI 1010 post saturates, leakage through the window grows, and the gap field must lie
  // between the unsaturated result at N I = 800 A and the leakage-free circuit estimate (an
  // upper bound: leakage flux adds to the post's saturation). Newton must still converge.
  const test::PotCore core;
  const cases::Material steel = test::aisi1010();
  const BhCurve curve(steel.bh, steel.name);
  MagnetostaticSolver solver(test::pot_core_problem(steel, 400, 6.0, 2),
                             test::pot_core_mesh(core, 2.0, 2));
  const Solution low = solver.solve({2.0});
  const Solution high = solver.solve({6.0});
  const double b_low = gap_centre_b(solver, low), b_high = gap_centre_b(solver, high);
  const double estimate = circuit_estimate(core, curve, 2400.0);
  std::printf("saturated: B_gap FE %.4f T (%.4f T at 800 A), circuit estimate %.4f T, Newton %d\n",
              b_high, b_low, estimate, high.newton.iterations);
  EXPECT_GT(b_high, b_low + 0.2);
  EXPECT_LT(b_high, estimate);
  EXPECT_LT(b_high, 0.8 * kMu0 * 2400 / core.gap);
  EXPECT_LT(high.newton.residual_history.back(), 1e-8);
}

TEST(IronCircuit, NewtonFailureThrowsConvergenceErrorWithTheResidual) {
  // Reference: one Newton step cannot solve the nonlinear problem to 1e-8.
  const test::PotCore core;
  SolveOptions options;
  options.newton.max_iterations = 1;
  MagnetostaticSolver solver(test::pot_core_problem(test::aisi1010(), 400, 2.0, 1),
                             test::pot_core_mesh(core, 1.0, 1), options);
  try {
    solver.solve();
    FAIL() << "no ConvergenceError";
  } catch (const ConvergenceError& e) {
    EXPECT_NE(std::string(e.what()).find("relative residual reached"), std::string::npos)
        << e.what();
  }
}

// A finite current whose load overflows (1e300 A x 400 turns): the message said "the residual
// diverged after 0 iteration(s); relative residual reached -nan"; it now says what overflowed.
TEST(IronCircuit, OverflowingSourceIsNamedNotNan) {
  const test::PotCore core;
  MagnetostaticSolver solver(test::pot_core_problem(test::aisi1010(), 400, 1e300, 1),
                             test::pot_core_mesh(core, 1.0, 1));
  try {
    solver.solve();
    FAIL() << "no ConvergenceError";
  } catch (const ConvergenceError& e) {
    EXPECT_EQ(std::string(e.what()),
              "the source of the field equation is not a finite number: the circuit currents "
              "(largest 1e+300 A) times the turns, a fixed current density or a magnet's "
              "coercivity is beyond double arithmetic");
  }
}

TEST(IronCircuit, DiscardedFactorisationSolvesLikeAFreshSolver) {
  // Reference: a newly constructed solver. After a solve at 0.05 A (which leaves a factorisation
  // behind), discard_factorisation() must make the 0.06 A solve bitwise the same as on a fresh
  // solver (sweeps rely on it: their rows must not depend on job order), from A = 0 and
  // warm-started from the 0.05 A field as sweeps do. Warm-started, the old factorisation is a
  // good preconditioner, so a solver that keeps it takes CG steps and ends in different last
  // bits: the last check shows the comparison can fail.
  const test::PotCore core;
  const cases::Problem problem = test::pot_core_problem(test::aisi1010(), 400, 2.0, 2);
  const mesh::Mesh mesh = test::pot_core_mesh(core, 1.0, 2);
  MagnetostaticSolver reused(problem, mesh);
  const Solution start = reused.solve({0.05});
  reused.discard_factorisation();
  const Solution a = reused.solve({0.06});
  reused.discard_factorisation();
  const Solution a_warm = reused.solve({0.06}, &start.a);
  MagnetostaticSolver fresh(problem, mesh);
  const Solution b = fresh.solve({0.06});
  MagnetostaticSolver fresh_warm(problem, mesh);
  const Solution b_warm = fresh_warm.solve({0.06}, &start.a);
  EXPECT_EQ(a.newton.iterations, b.newton.iterations);
  EXPECT_EQ(a.flux_linkage[0], b.flux_linkage[0]);
  EXPECT_EQ(a.incremental_inductance[0], b.incremental_inductance[0]);
  EXPECT_EQ((a.a - b.a).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(a_warm.flux_linkage[0], b_warm.flux_linkage[0]);
  EXPECT_EQ(a_warm.incremental_inductance[0], b_warm.incremental_inductance[0]);
  EXPECT_EQ((a_warm.a - b_warm.a).cwiseAbs().maxCoeff(), 0.0);
  MagnetostaticSolver kept(problem, mesh);
  kept.solve({0.05});
  const Solution c = kept.solve({0.06}, &start.a);
  std::printf("max |A_kept - A_fresh| %.3g Wb/m (warm-started)\n",
              (c.a - b_warm.a).cwiseAbs().maxCoeff());
  EXPECT_NE((c.a - b_warm.a).cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace rheomag::magnetostatics
