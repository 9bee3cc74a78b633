// Long solenoid: B inside = mu0 N I / l.

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "magnetostatics/solver.hpp"
#include "tests/magnetostatics/coil_problem.hpp"
#include "tests/magnetostatics/structured_mesh.hpp"

namespace rheomag::magnetostatics {
namespace {

TEST(Solenoid, InfinitelyLongSolenoidByNaturalBoundaries) {
  // Reference: Ampere's law for an infinitely long solenoid, B_z = mu0 N I / l inside and 0
  // outside. One period l of it is modelled with natural boundaries on z = 0, z = l and r = R
  // (n x H = 0: no radial field, no field outside); A = 0 on the axis. Tolerance 0.5 % (issue
  // 2); B_r inside < 1e-3 of B_z; outside |B| < 5 % (P1) / 0.5 % (P2) of the inside value (the
  // interpolation error of the exterior potential A = Phi / (2 pi r), h = 2 mm at r = 20 mm).
  const double length = 10e-3, turns = 50, current = 1.0;
  const double expected = kMu0 * turns * current / length;
  for (int order : {1, 2}) {
    cases::Problem p;
    p.symmetry = cases::Symmetry::axisymmetric;
    p.order = order;
    p.outer = cases::OuterBoundary::none;
    p.geometry.regions = {{{5e-3, 5e-3}, "air"}, {{11e-3, 5e-3}, "coil"}};
    p.materials = {{"air", 1.0, {}, 0.0, "vacuum"}};
    p.regions = {{0, -1, 0.0}, {0, 0, turns}};
    p.circuits = {{"coil", current}};
    const auto r =
        test::join(test::join(test::uniform(0, 10e-3, 10), test::uniform(10e-3, 12e-3, 4)),
                   test::uniform(12e-3, 30e-3, 9));
    const mesh::Mesh m =
        test::structured_mesh(r, test::uniform(0, length, 5), order,
                              [](double rr, double) { return rr > 10e-3 && rr < 12e-3 ? 1 : 0; });
    MagnetostaticSolver solver(p, m);
    const Solution s = solver.solve();
    std::array<double, 2> inside{}, outside{};
    ASSERT_TRUE(flux_density_at(solver, s, {5e-3, 3e-3}, -1, inside));
    ASSERT_TRUE(flux_density_at(solver, s, {20e-3, 3e-3}, -1, outside));
    std::printf("P%d: B_z inside %.6e T (expected %.6e), |B| outside %.2e T\n", order, inside[1],
                expected, std::hypot(outside[0], outside[1]));
    EXPECT_NEAR(inside[1], expected, 0.005 * expected);
    EXPECT_LT(std::abs(inside[0]), 1e-3 * expected);
    EXPECT_LT(std::hypot(outside[0], outside[1]), (order == 1 ? 0.05 : 0.005) * expected);
  }
}

TEST(Solenoid, FiniteLongSolenoidInOpenSpace) {
  // Reference: centre field of a finite solenoid of uniform current density J between radii
  // a1, a2 and length l (Biot-Savart integrated over the winding):
  //   B0 = mu0 J (l/2) ln[(a2 + sqrt(a2^2 + l^2/4)) / (a1 + sqrt(a1^2 + l^2/4))],
  // which for l / D = 18 is mu0 N I / l (1 - 0.18 %). Tolerances: 0.5 % against mu0 N I / l
  // (issue 2), 0.1 % against B0. Real path: open boundary, CGAL mesh, P2.
  const double a1 = 10e-3, a2 = 11e-3, length = 0.4, turns = 400, current = 2.0;
  const cases::Problem p = test::rectangles_problem(
      {{a1, a2, -0.5 * length, 0.5 * length, "coil", 0, turns, 1e-3}},
      {{"copper", 1.0, {}, 5.8e7, "nonmagnetic"}}, current, cases::OuterBoundary::open, 2);
  const SolveResult result = solve_problem(p);
  std::array<double, 2> centre{};
  ASSERT_TRUE(flux_density_at(*result.solver, result.solution, {1e-3, 0.0}, -1, centre));
  const double j = turns * current / ((a2 - a1) * length), half = 0.5 * length;
  const double exact =
      kMu0 * j * half * std::log((a2 + std::hypot(a2, half)) / (a1 + std::hypot(a1, half)));
  const double ideal = kMu0 * turns * current / length;
  std::printf("B_z centre %.6e T, exact finite %.6e T, mu0 N I / l %.6e T, %d dofs\n", centre[1],
              exact, ideal, result.results.dofs);
  EXPECT_NEAR(centre[1], ideal, 0.005 * ideal);
  EXPECT_NEAR(centre[1], exact, 0.001 * exact);
}

TEST(Solenoid, PlanarCurrentSlabFieldAndInductance) {
  // Planar analogue of the infinite solenoid (checks the planar path and the depth scaling): a
  // slab a < x < b of N turns carrying I along z, height h, A = 0 on x = 0, natural boundaries
  // elsewhere. Ampere: B_y = -mu0 N I / h for x < a, 0 for x > b; flux linkage
  // lambda = depth (N / (t h)) integral A dA gives L = mu0 N^2 depth (a + t/3) / h, t = b - a.
  // A is piecewise quadratic in x, so P2 is exact: tolerance 1e-9 relative; P1 0.5 %.
  const double a = 4e-3, b = 6e-3, width = 10e-3, height = 5e-3, depth = 0.2;
  const double turns = 30, current = 1.5;
  for (int order : {2, 1}) {
    cases::Problem p;
    p.symmetry = cases::Symmetry::planar;
    p.depth = depth;
    p.order = order;
    p.outer = cases::OuterBoundary::none;
    p.geometry.regions = {{{2e-3, 2e-3}, "air"}, {{5e-3, 2e-3}, "coil"}};
    p.materials = {{"air", 1.0, {}, 0.0, "vacuum"}};
    p.regions = {{0, -1, 0.0}, {0, 0, turns}};
    p.circuits = {{"coil", current}};
    p.boundaries = {{"A = 0", cases::BoundaryKind::prescribed_a, 0.0, 0.0, 0.0}};
    const auto x = test::join(test::join(test::uniform(0, a, 8), test::uniform(a, b, 8)),
                              test::uniform(b, width, 8));
    const mesh::Mesh m = test::structured_mesh(
        x, test::uniform(0, height, 4), order,
        [&](double xx, double) { return xx > a && xx < b ? 1 : 0; }, {0, -1, -1, -1});
    MagnetostaticSolver solver(p, m);
    const Solution s = solver.solve();
    std::array<double, 2> inside{};
    ASSERT_TRUE(flux_density_at(solver, s, {2e-3, 1e-3}, -1, inside));
    const double b_expected = -kMu0 * turns * current / height;
    const double l_expected = kMu0 * turns * turns * depth * (a + (b - a) / 3) / height;
    const double tolerance = order == 2 ? 1e-9 : 5e-3;
    std::printf("planar P%d: B_y %.6e T (expected %.6e), L %.6e H (expected %.6e)\n", order,
                inside[1], b_expected, s.flux_linkage[0] / current, l_expected);
    EXPECT_NEAR(inside[1], b_expected, tolerance * std::abs(b_expected));
    EXPECT_NEAR(s.flux_linkage[0] / current, l_expected, tolerance * l_expected);
  }
}

}  // namespace
}  // namespace rheomag::magnetostatics
