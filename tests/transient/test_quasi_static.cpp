// The quasi-static reduction of a step response (transient/quasi_static.hpp) on the conducting
// cylinder in a long solenoid (tests/transient/cylinder.hpp): its eddy-current load against the
// analytic one, its mean delay against the full transient's, its rise times against the full
// transient where the steel is thin against its skin depth, and on a saturating cylinder; a table
// that reuses a nearby design's states.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <tuple>
#include <vector>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "magnetostatics/solver.hpp"
#include "tests/transient/cylinder.hpp"
#include "transient/quasi_static.hpp"
#include "transient/transient_solver.hpp"

// Boost 1.74's pchip.hpp calls isnan unqualified in a template; make std::isnan visible there.
using std::isnan;
#include <boost/math/interpolators/pchip.hpp>

namespace {

using namespace rheomag;
using transient::Drive;
using transient::TransientOptions;

/// The reduction and the full transient of one voltage step on one cylinder.
struct Compared {
  transient::QuasiStaticTable table;
  transient::QuasiStaticStep reduced;
  transient::TransientResult full;
};

Compared compare(const test::Cylinder& c, const cases::Problem& problem, double voltage,
                 double resistance, double duration, int points = 16) {
  magnetostatics::MagnetostaticSolver statics(problem, c.mesh(24));
  transient::TransientSolver solver(statics, transient::eddy_coefficients(statics.problem(), {}));
  Compared out;
  const double final_current = voltage / resistance;
  out.table = transient::quasi_static_table(solver, 0.0, final_current, points);
  out.reduced = transient::quasi_static_step(out.table, 0.0, final_current, resistance);
  TransientOptions o;
  o.drive = Drive::voltage;
  o.value = voltage;
  o.resistance = resistance;
  o.duration = duration;
  o.tolerance = 1e-6;
  out.full = solver.run(o);
  return out;
}

/// integral of (1 - lambda(t) / lambda_final) dt over the run (trapezoids; the run is long
/// enough for the rest to be below 1e-6 of it).
double mean_delay(const transient::TransientResult& r) {
  double sum = 0.0;
  for (std::size_t k = 1; k < r.time.size(); ++k) {
    const double a = 1.0 - r.flux_linkage[k - 1] / r.final_flux_linkage;
    const double b = 1.0 - r.flux_linkage[k] / r.final_flux_linkage;
    sum += 0.5 * (a + b) * (r.time[k] - r.time[k - 1]);
  }
  return sum;
}

// Reference: in a long solenoid the static field in the cylinder is uniform, A = B r / 2 with
// B = mu N I / length, so the eddy-current load D = integral sigma (dA/dI)^2 dV
// = sigma pi a^4 (mu N / length)^2 length / 8 (the winding carries none). A linear device's
// reduction is one exponential of time constant L/R + D/L, so its t63 is that time constant and
// its t90 ln(10) times it; P2 elements hold A = B r / 2 exactly (tolerance 1e-6).
TEST(QuasiStaticResponse, EddyLoadAndTimeConstantOfALinearCylinder) {
  const test::Cylinder c;
  const Compared r = compare(c, c.problem(), 1.0, 0.2, 2.0);
  const double mu = kMu0 * c.mu_r, field_per_current = mu * c.turns / c.length;
  const double load = c.sigma * std::numbers::pi * std::pow(c.a, 4) * field_per_current *
                      field_per_current * c.length / 8.0;
  const transient::QuasiStaticPoint& p = r.table.points.front();
  const double tau = p.inductance / 0.2 + load / p.inductance;
  std::printf("eddy load %.8g H s (analytic %.8g), L %.6g H, tau %.6g s, t63 %.6g s\n", p.eddy_load,
              load, p.inductance, tau, *r.reduced.t63);
  EXPECT_NEAR(p.eddy_load / load, 1.0, 1e-6);
  EXPECT_NEAR(r.table.points.back().eddy_load / load, 1.0, 1e-6);  // linear: the same
  ASSERT_TRUE(r.reduced.t63 && r.reduced.t90);
  EXPECT_NEAR(*r.reduced.t63 / tau, 1.0, 1e-6);
  EXPECT_NEAR(*r.reduced.t90 / (std::log(10.0) * tau), 1.0, 1e-6);
}

// Reference: for a linear device the reduction's mean delay (first moment of 1 - lambda /
// lambda_final, here its time constant) equals the exact response's, L/R + D/L, whatever the
// skin depth (the impedance's first two moments are matched). The full transient (adaptive
// midpoint, 1e-6) over 2 s (about 11 time constants) is the reference; tolerance 0.2 % (its
// time steps and the trapezoids). Here the cylinder's diffusion time (108.6 ms) is as long as
// L/R, so the reduction's t90 is visibly off: printed, and it must be within 10 %.
TEST(QuasiStaticResponse, MeanDelayOfALinearCylinderIsTheFullTransients) {
  const test::Cylinder c;
  const Compared r = compare(c, c.problem(), 1.0, 0.2, 2.0);
  ASSERT_TRUE(r.reduced.t63 && r.reduced.t90 && r.full.t90);
  const double delay = mean_delay(r.full);
  std::printf("mean delay: full %.6g s, reduced %.6g s; t90 full %.6g s, reduced %.6g s\n", delay,
              *r.reduced.t63, *r.full.t90, *r.reduced.t90);
  EXPECT_NEAR(*r.reduced.t63 / delay, 1.0, 2e-3);
  EXPECT_NEAR(*r.reduced.t90 / *r.full.t90, 1.0, 0.10);
}

// Where the steel is thin against its skin depth over the response (sigma 100 times lower:
// diffusion time 1.09 ms against L/R = 99 ms), the field keeps its static shape and the
// reduction gives the full transient's rise times. Reference: the full transient (adaptive,
// 1e-6); tolerance 0.3 % on t63 and t90.
TEST(QuasiStaticResponse, RiseTimesOfAThinConductorAreTheFullTransients) {
  test::Cylinder c;
  c.sigma = 5e4;
  const Compared r = compare(c, c.problem(), 1.0, 0.2, 1.0);
  ASSERT_TRUE(r.reduced.t63 && r.reduced.t90 && r.full.t63 && r.full.t90);
  std::printf("t63 full %.6g s, reduced %.6g s; t90 full %.6g s, reduced %.6g s\n", *r.full.t63,
              *r.reduced.t63, *r.full.t90, *r.reduced.t90);
  EXPECT_NEAR(*r.reduced.t63 / *r.full.t63, 1.0, 3e-3);
  EXPECT_NEAR(*r.reduced.t90 / *r.full.t90, 1.0, 3e-3);
}

// A saturating cylinder (B-H knee at 1.5 T) driven into saturation and back (4 V through
// 0.2 Ohm: 20 A, H0 = 100 kA/m) with the thin-conductor sigma: the reduction follows the changing
// inductance. Reference: the full transient (adaptive, 1e-6) for the step on and the step off;
// tolerance 1 % on t90. The knee lies at 1 % of the range, within the first of 16 equal
// intervals: the table's refinement must find it (16 starting currents agree with 64 to 0.5 %).
TEST(QuasiStaticResponse, SaturatingStepOnAndOffFollowTheFullTransient) {
  test::Cylinder c;
  c.sigma = 5e4;
  const cases::Problem problem = c.problem(test::kSaturatingBh);
  magnetostatics::MagnetostaticSolver statics(problem, c.mesh(24));
  transient::TransientSolver solver(statics, transient::eddy_coefficients(statics.problem(), {}));
  const double resistance = 0.2, final_current = 20.0;
  const auto table = transient::quasi_static_table(solver, 0.0, final_current, 16);
  const auto fine = transient::quasi_static_table(solver, 0.0, final_current, 64);
  for (const bool on : {true, false}) {
    const double from = on ? 0.0 : final_current, to = on ? final_current : 0.0;
    const auto reduced = transient::quasi_static_step(table, from, to, resistance);
    const auto reduced_fine = transient::quasi_static_step(fine, from, to, resistance);
    TransientOptions o;
    o.drive = Drive::voltage;
    o.value = to * resistance;
    o.from_current = from;
    o.resistance = resistance;
    o.duration = 0.5;
    o.tolerance = 1e-6;
    const transient::TransientResult full = solver.run(o);
    ASSERT_TRUE(reduced.t90 && reduced_fine.t90 && full.t90);
    std::printf(
        "step %s: t90 full %.6g s, reduced %.6g s on %zu currents (from 64: %.6g s on %zu)\n",
        on ? "on" : "off", *full.t90, *reduced.t90, table.points.size(), *reduced_fine.t90,
        fine.points.size());
    EXPECT_NEAR(*reduced.t90 / *full.t90, 1.0, 0.01);
    EXPECT_NEAR(*reduced.t90 / *reduced_fine.t90, 1.0, 0.005);
  }
}

/// A saturating cylinder's table at `turns` on a mesh of `cells` (the same mesh for any turns)
/// from `points` starting currents.
transient::QuasiStaticTable saturating_table(double turns, int cells,
                                             const transient::QuasiStaticReuse& reuse = {},
                                             int points = 16) {
  test::Cylinder c;
  c.sigma = 5e4;
  c.turns = turns;
  magnetostatics::MagnetostaticSolver statics(c.problem(test::kSaturatingBh), c.mesh(cells));
  transient::TransientSolver solver(statics, transient::eddy_coefficients(statics.problem(), {}));
  return transient::quasi_static_table(solver, 0.0, 20.0, points, reuse);
}

double step_on_t90(const transient::QuasiStaticTable& table) {
  return *transient::quasi_static_step(table, 0.0, 20.0, 0.2).t90;
}

// Reference: the same design's table built cold. Started from a nearby design's states (10 and
// 10.2 turns: the knee moves by 2 %), the table is the same to Newton's tolerance (1e-8 relative
// residual; tolerance 1e-6 on every coefficient) in fewer Newton iterations. On another mesh the
// states are not used (the table is bitwise the cold one).
TEST(QuasiStaticResponse, TableStartedFromANearbyDesignIsTheSameInFewerNewtonSteps) {
  transient::QuasiStaticStart nearby;
  const auto earlier = saturating_table(10.0, 24, {.keep = &nearby});
  ASSERT_EQ(nearby.fields.size(), earlier.points.size());
  EXPECT_EQ(nearby.fractions.front(), 0.0);
  EXPECT_EQ(nearby.fractions.back(), 1.0);
  const auto cold = saturating_table(10.2, 24);
  const auto warm = saturating_table(10.2, 24, {.start = &nearby});
  std::printf("Newton iterations: cold %d, from the nearby design %d (%zu currents)\n",
              cold.newton_iterations, warm.newton_iterations, cold.points.size());
  EXPECT_LT(warm.newton_iterations, cold.newton_iterations);
  ASSERT_EQ(warm.points.size(), cold.points.size());
  auto near = [](double a, double b) { return std::abs(a - b) <= 1e-6 * std::abs(b) + 1e-15; };
  for (std::size_t k = 0; k < cold.points.size(); ++k) {
    const auto &w = warm.points[k], &c = cold.points[k];
    EXPECT_EQ(w.current, c.current);
    EXPECT_TRUE(near(w.flux_linkage, c.flux_linkage)) << k;
    EXPECT_TRUE(near(w.inductance, c.inductance)) << k;
    EXPECT_TRUE(near(w.eddy_load, c.eddy_load)) << k;
  }
  const auto other_mesh = saturating_table(10.2, 16, {.start = &nearby});
  const auto other_mesh_cold = saturating_table(10.2, 16);
  EXPECT_EQ(other_mesh.newton_iterations, other_mesh_cold.newton_iterations);
  EXPECT_EQ(other_mesh.points.back().eddy_load, other_mesh_cold.points.back().eddy_load);
}

// A finite-difference stencil on the grid of its centre: every neighbour's table has the
// centre's currents (no refinement of its own) and starts from the centre's states (fewer Newton
// steps: tolerance 70 % of the cold count), so dt90/dturns by central differences at steps
// h and h/2 agree (tolerance 1 %: their truncation errors differ by O(h^2)), and the t90 of the
// fixed grid is the refined table's to the refinement's own accuracy (0.5 %, as 16 against 64
// starting currents above).
TEST(QuasiStaticResponse, FiniteDifferenceNeighboursOnTheCentresGridAreSmooth) {
  transient::QuasiStaticStart centre;
  const double turns = 10.0;
  const auto at_centre = saturating_table(turns, 24, {.keep = &centre});
  auto neighbour = [&](double t) {  // 8 starting currents: the centre's 16-based grid instead
    return saturating_table(t, 24, {.start = &centre, .fixed_grid = true}, 8);
  };
  const auto up = neighbour(turns * 1.01);
  ASSERT_EQ(up.points.size(), at_centre.points.size());
  // An optimiser's stencil (a 0.1 % step) from the centre's states: measured 110 Newton
  // iterations against 174 cold.
  const int near_iterations = neighbour(turns * 1.001).newton_iterations;
  const int cold_iterations = saturating_table(turns * 1.001, 24).newton_iterations;
  std::printf("Newton iterations at a 0.1 %% step: %d from the centre, %d cold\n", near_iterations,
              cold_iterations);
  EXPECT_LT(near_iterations, 0.7 * cold_iterations);
  for (std::size_t k = 0; k < up.points.size(); ++k)
    EXPECT_NEAR(up.points[k].current, at_centre.points[k].current, 1e-13 * 20.0);
  double slope[2];
  for (int halving = 0; halving < 2; ++halving) {
    const double h = turns * 0.01 / (1 << halving);
    slope[halving] =
        (step_on_t90(neighbour(turns + h)) - step_on_t90(neighbour(turns - h))) / (2.0 * h);
  }
  std::printf("dt90/dturns: %.6g s (h = 1 %%), %.6g s (h = 0.5 %%)\n", slope[0], slope[1]);
  EXPECT_NEAR(slope[1] / slope[0], 1.0, 0.01);
  EXPECT_NEAR(step_on_t90(up) / step_on_t90(saturating_table(turns * 1.01, 24)), 1.0, 0.005);
}

/// The saturating cylinder's table at `turns` and radius `radius` [m] (the mesh moved with the
/// radius, its nodes kept: an optimiser's morphed mesh) on 24 cells, 8 starting currents, Newton
/// to the relative residual `tolerance`, from 0 to `high` [A].
transient::QuasiStaticTable cylinder_table(double turns, double radius,
                                           const transient::QuasiStaticReuse& reuse = {},
                                           double tolerance = 1e-8, double high = 20.0) {
  test::Cylinder c;
  c.sigma = 5e4;
  c.turns = turns;
  c.a = radius;
  magnetostatics::SolveOptions options;
  options.newton.relative_tolerance = tolerance;
  magnetostatics::MagnetostaticSolver statics(c.problem(test::kSaturatingBh), c.mesh(24), options);
  transient::TransientSolver solver(statics, transient::eddy_coefficients(statics.problem(), {}));
  return transient::quasi_static_table(solver, 0.0, high, 8, reuse);
}

// Linearised finite-difference neighbours (QuasiStaticReuse::linearise) at the optimiser's
// default step (0.1 %) in the turns and in the radius (the mesh morphed), and at 0.01 %.
// Reference: the neighbour's difference from the centre with both solved by Newton to a 1e-10
// relative residual. Each point's change of lambda, L_d and D (where it is at least 1 % of the
// step) is within 1 % of it, no worse than from two Newton tables at the default tolerance
// (1e-8), and so is dt90's. No Newton step is taken. With a memory budget for the factorisations
// only the states that kept theirs are linearised. A centre 20 % away does not contract: those
// states are solved by Newton and match the Newton table to its tolerance (1e-6).
TEST(QuasiStaticResponse, LinearisedNeighboursMatchNewtonsToSecondOrder) {
  const double turns = 10.0, radius = 0.01;
  transient::QuasiStaticStart centre, centre_exact;
  const auto at_centre =
      cylinder_table(turns, radius, {.keep = &centre, .keep_factor_bytes = std::size_t{1} << 30});
  const auto at_centre_exact = cylinder_table(turns, radius, {.keep = &centre_exact}, 1e-10);
  ASSERT_EQ(at_centre_exact.points.size(), at_centre.points.size());
  ASSERT_EQ(centre.factors.size(), at_centre.points.size());
  for (const auto& f : centre.factors) ASSERT_TRUE(f);
  const transient::QuasiStaticReuse newton{.start = &centre, .fixed_grid = true};
  const transient::QuasiStaticReuse linear{.start = &centre, .fixed_grid = true, .linearise = true};
  const transient::QuasiStaticReuse exact{.start = &centre_exact, .fixed_grid = true};
  for (const auto& [t, r, h] :
       {std::tuple{turns * 1.001, radius, 1e-3}, std::tuple{turns, radius * 1.001, 1e-3},
        std::tuple{turns, radius * 1.0001, 1e-4}}) {
    const auto solved = cylinder_table(t, r, newton);
    const auto linearised = cylinder_table(t, r, linear);
    const auto reference = cylinder_table(t, r, exact, 1e-10);
    ASSERT_EQ(linearised.points.size(), at_centre.points.size());
    EXPECT_EQ(linearised.linearised, static_cast<int>(at_centre.points.size()));
    EXPECT_EQ(linearised.newton_iterations, 0);
    EXPECT_EQ(linearised.same_ampere_turns, 0);  // the same currents: other ampere-turns
    double worst = 0.0, worst_newton = 0.0;
    auto check = [&](auto of, const char* what) {
      for (std::size_t k = 0; k < at_centre.points.size(); ++k) {
        const double change = of(reference.points[k]) - of(at_centre_exact.points[k]);
        if (change == 0.0 || std::abs(change) < 0.01 * h * std::abs(of(reference.points[k])))
          continue;
        const double error = std::abs(of(linearised.points[k]) - of(at_centre.points[k]) - change) /
                             std::abs(change);
        const double newton_error =
            std::abs(of(solved.points[k]) - of(at_centre.points[k]) - change) / std::abs(change);
        worst = std::max(worst, error);
        worst_newton = std::max(worst_newton, newton_error);
        EXPECT_LE(error, std::max(0.01, newton_error)) << what << " at point " << k;
      }
    };
    check([](const transient::QuasiStaticPoint& p) { return p.flux_linkage; }, "lambda");
    check([](const transient::QuasiStaticPoint& p) { return p.inductance; }, "L_d");
    check([](const transient::QuasiStaticPoint& p) { return p.eddy_load; }, "D");
    const double dt = step_on_t90(reference) - step_on_t90(at_centre_exact);
    const double dt_linearised = step_on_t90(linearised) - step_on_t90(at_centre);
    const double dt_newton = step_on_t90(solved) - step_on_t90(at_centre);
    std::printf(
        "turns %g, radius %g mm: worst error of a change: linearised %.3g, Newton %.3g; dt90 "
        "%.6g s, linearised %.6g s, Newton %.6g s\n",
        t, r * 1e3, worst, worst_newton, dt, dt_linearised, dt_newton);
    EXPECT_NEAR(dt_linearised / dt, 1.0, std::max(0.01, std::abs(dt_newton / dt - 1.0)));
  }
  // A budget of about 3 states' factorisations: the first states solved (the lowest starting
  // currents) keep theirs and are linearised, the others are solved by Newton.
  transient::QuasiStaticStart budgeted;
  cylinder_table(turns, radius,
                 {.keep = &budgeted, .keep_factor_bytes = 3 * centre.factors[1]->bytes()});
  ASSERT_EQ(budgeted.factors.size(), at_centre.points.size());
  int kept = 0;
  for (const auto& f : budgeted.factors) kept += f != nullptr;
  EXPECT_TRUE(budgeted.factors.front() && !budgeted.factors.back());
  EXPECT_GE(kept, 2);
  EXPECT_LE(kept, 4);
  const auto partly = cylinder_table(turns * 1.001, radius,
                                     {.start = &budgeted, .fixed_grid = true, .linearise = true});
  EXPECT_EQ(partly.linearised, kept);
  const auto far = cylinder_table(turns * 1.2, radius, linear);
  const auto far_newton = cylinder_table(turns * 1.2, radius, newton);
  std::printf("20 %% away: %d of %zu states linearised\n", far.linearised, far.points.size());
  EXPECT_LT(far.linearised, static_cast<int>(far.points.size()));
  for (std::size_t k = 0; k < far.points.size(); ++k) {
    EXPECT_NEAR(far.points[k].flux_linkage, far_newton.points[k].flux_linkage,
                1e-6 * std::abs(far_newton.points[k].flux_linkage));
    EXPECT_NEAR(far.points[k].inductance, far_newton.points[k].inductance,
                1e-6 * far_newton.points[k].inductance);
  }
}

// A finite-difference neighbour in the turns alone (N' = s N, s = 1.001) whose range is the
// voltage step's V / R' = 20 A / s (R in proportion to the turns): its states carry the centre's
// ampere-turns at the same fractions, so QuasiStaticReuse::linearise takes the centre's states
// themselves, without a chord step. Exact scaling (A(N', i / s) = A(N, i)): lambda' = s lambda to
// rounding (1e-12), L_d' = s^2 L_d and D' = s^2 D to the slope steps' settling (1e-6 of them,
// 5e-4 of their 2e-3 change; measured up to 2.1e-7 for D). Reference for the differences: both
// tables solved by Newton to a 1e-10 relative residual; dt90's change within 1 % of it, as the
// other linearised neighbours'.
TEST(QuasiStaticResponse, TurnsNeighbourOnItsVoltageRangeIsTheCentresStatesScaled) {
  const double turns = 10.0, radius = 0.01, s = 1.001;
  transient::QuasiStaticStart centre, centre_exact;
  const auto at_centre =
      cylinder_table(turns, radius, {.keep = &centre, .keep_factor_bytes = std::size_t{1} << 30});
  const auto at_centre_exact = cylinder_table(turns, radius, {.keep = &centre_exact}, 1e-10);
  const auto neighbour = cylinder_table(
      turns * s, radius, {.start = &centre, .fixed_grid = true, .linearise = true}, 1e-8, 20.0 / s);
  const auto reference = cylinder_table(
      turns * s, radius, {.start = &centre_exact, .fixed_grid = true}, 1e-10, 20.0 / s);
  const auto n = static_cast<int>(at_centre.points.size());
  ASSERT_EQ(static_cast<int>(neighbour.points.size()), n);
  EXPECT_EQ(neighbour.linearised, n);
  EXPECT_EQ(neighbour.same_ampere_turns, n - 1);  // all but 0 A, which is the centre's anyway
  EXPECT_EQ(neighbour.newton_iterations, 0);
  for (int k = 1; k < n; ++k) {
    const transient::QuasiStaticPoint &p = neighbour.points[k], &c = at_centre.points[k];
    EXPECT_NEAR(p.current * s / c.current, 1.0, 1e-12) << k;
    EXPECT_NEAR(p.flux_linkage / (s * c.flux_linkage), 1.0, 1e-12) << k;
    EXPECT_NEAR(p.inductance / (s * s * c.inductance), 1.0, 1e-6) << k;
    EXPECT_NEAR(p.eddy_load / (s * s * c.eddy_load), 1.0, 1e-6) << k;
  }
  // The voltage step's t90 (R = 0.2 Ohm x the turns' ratio) on each table's own range.
  auto t90 = [](const transient::QuasiStaticTable& table, double ratio) {
    return *transient::quasi_static_step(table, 0.0, table.points.back().current, 0.2 * ratio).t90;
  };
  const double dt = t90(reference, s) - t90(at_centre_exact, 1.0);
  const double dt_neighbour = t90(neighbour, s) - t90(at_centre, 1.0);
  std::printf("dt90 of a 0.1 %% change of turns on V / R: %.6g s, from the scaled states %.6g s\n",
              dt, dt_neighbour);
  EXPECT_NEAR(dt_neighbour / dt, 1.0, 0.01);
}

// Reference: the table from 128 equal starting currents (each of their intervals is checked too,
// so 255 or more). From 8 starting currents the table halves only the intervals whose midpoint
// its interpolants missed by more than kQuasiStaticTableTolerance, so it must find the knee at
// 1 % of the range by itself (L_d falls 30-fold across it): the step on's and off's t90 within
// 0.2 % of the fine table's (measured -0.08 % and -0.06 %), on under a third of its currents.
// L_d and D interpolated at every current of the fine table within twice and four times the
// tolerance (D goes about as L_d squared): the check samples one midpoint per interval, so a
// quarter point of a settled interval can miss by more (measured 5.2 % and 11 %, in the knee).
TEST(QuasiStaticResponse, TableRefinedWhereItMissedAMidpointMatchesAFineTable) {
  const auto fine = saturating_table(10.0, 24, {}, 128);
  const auto table = saturating_table(10.0, 24, {}, 8);
  std::printf("%zu currents against %zu\n", table.points.size(), fine.points.size());
  EXPECT_LT(3 * table.points.size(), fine.points.size());
  for (const bool on : {true, false}) {
    const double from = on ? 0.0 : 20.0, to = on ? 20.0 : 0.0;
    const double t90 = *transient::quasi_static_step(table, from, to, 0.2).t90;
    const double fine_t90 = *transient::quasi_static_step(fine, from, to, 0.2).t90;
    std::printf("step %s: t90 %.6g s, fine %.6g s\n", on ? "on" : "off", t90, fine_t90);
    EXPECT_NEAR(t90 / fine_t90, 1.0, 2e-3);
  }
  using Pchip = boost::math::interpolators::pchip<std::vector<double>>;
  std::vector<double> current, inductance, eddy_load;
  for (const auto& p : table.points) {
    current.push_back(p.current);
    inductance.push_back(p.inductance);
    eddy_load.push_back(p.eddy_load);
  }
  const Pchip l(std::vector<double>(current), std::move(inductance)),
      d(std::move(current), std::move(eddy_load));
  double worst_l = 0.0, worst_d = 0.0;
  for (const auto& p : fine.points) {
    worst_l = std::max(worst_l, std::abs(l(p.current) / p.inductance - 1.0));
    worst_d = std::max(worst_d, std::abs(d(p.current) / p.eddy_load - 1.0));
  }
  std::printf("worst interpolation error: L_d %.3g, D %.3g\n", worst_l, worst_d);
  EXPECT_LT(worst_l, 2.0 * transient::kQuasiStaticTableTolerance);
  EXPECT_LT(worst_d, 4.0 * transient::kQuasiStaticTableTolerance);
}

// Without any conductor an ideal current step reaches the field at once; a step outside the
// table or without change is refused.
TEST(QuasiStaticResponse, CurrentStepWithoutConductorsAndBadSteps) {
  test::Cylinder c;
  c.sigma = 0.0;
  magnetostatics::MagnetostaticSolver statics(c.problem(), c.mesh(8));
  transient::TransientSolver solver(statics, transient::eddy_coefficients(statics.problem(), {}));
  const auto table = transient::quasi_static_table(solver, 0.0, 2.0, 4);
  const double infinite = std::numeric_limits<double>::infinity();
  const auto step = transient::quasi_static_step(table, 0.0, 1.0, infinite);
  ASSERT_TRUE(step.t90);
  EXPECT_EQ(*step.t90, 0.0);
  EXPECT_THROW(transient::quasi_static_step(table, 0.0, 3.0, 1.0), InputError);
  EXPECT_THROW(transient::quasi_static_step(table, 1.0, 1.0, 1.0), InputError);
  EXPECT_THROW(transient::quasi_static_table(solver, 0.0, 2.0, 3), InputError);
  EXPECT_THROW(transient::quasi_static_table(solver, 2.0, 2.0, 8), InputError);
}

}  // namespace
