// Bad input reaching the solver and the domain closing: one clear InputError each.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "magnetostatics/domain.hpp"
#include "magnetostatics/solver.hpp"
#include "tests/magnetostatics/structured_mesh.hpp"

namespace rheomag::magnetostatics {
namespace {

cases::Problem square(cases::Symmetry symmetry) {
  cases::Problem p;
  p.symmetry = symmetry;
  p.outer = cases::OuterBoundary::none;
  p.geometry.source = "square.toml";
  p.geometry.regions = {{{0.5, 0.5}, "coil"}};
  p.materials = {{"air", 1.0, {}, 0.0, "vacuum"}};
  p.regions = {{0, 0, 10.0}};
  p.circuits = {{"coil", 1.0}};
  return p;
}

mesh::Mesh square_mesh(double r0, std::array<int, 4> markers = {-1, -1, -1, -1}) {
  return test::structured_mesh(
      test::uniform(r0, r0 + 1.0, 2), test::uniform(0.0, 1.0, 2), 2,
      [](double, double) { return 0; }, markers);
}

void expect_input_error(const std::function<void()>& action, const std::string& fragment) {
  try {
    action();
    FAIL() << "no InputError (expected one mentioning '" << fragment << "')";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(SolverInput, UndeterminedPotentialIsAnInputError) {
  // Planar, no boundary condition: A only defined up to a constant, which is pinned at one node;
  // but the square's one-sided coil carries a net current that dA/dn = 0 cannot return.
  MagnetostaticSolver planar(square(cases::Symmetry::planar), square_mesh(0.0));
  EXPECT_GE(planar.dofs().gauge_node, 0);
  expect_input_error([&] { planar.solve(); }, "net current");
  // Axisymmetric off the axis with natural boundaries only: A = C/r is free.
  expect_input_error(
      [] { MagnetostaticSolver s(square(cases::Symmetry::axisymmetric), square_mesh(1.0)); },
      "no node on the axis");
}

TEST(SolverInput, RegionWithoutMaterialIsNamed) {
  cases::Problem p = square(cases::Symmetry::axisymmetric);
  p.regions[0].material = -1;
  expect_input_error([&] { MagnetostaticSolver s(p, square_mesh(0.0)); },
                     "region 'coil' has no material");
}

TEST(SolverInput, BadCurrentsAndMarkers) {
  MagnetostaticSolver solver(square(cases::Symmetry::axisymmetric), square_mesh(0.0));
  expect_input_error([&] { solver.solve({1.0, 2.0}); }, "2 current(s) given for 1 circuit(s)");
  expect_input_error([&] { solver.solve({std::numeric_limits<double>::quiet_NaN()}); },
                     "not a finite number");
  expect_input_error(
      [] {
        MagnetostaticSolver s(square(cases::Symmetry::axisymmetric),
                              square_mesh(0.0, {-1, 3, -1, -1}));
      },
      "boundary marker 3");
}

TEST(SolverInput, DomainClosingChecksItsInput) {
  cases::Problem p = square(cases::Symmetry::axisymmetric);
  p.outer = cases::OuterBoundary::open;
  p.geometry.points = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
  p.outer_radius_factor = 1.0;
  expect_input_error([&] { close_domain(p); }, "outer_radius_factor");
  p.outer_radius_factor = 5.0;
  p.geometry.points[0].r = -0.5;
  expect_input_error([&] { close_domain(p); }, "r >= 0");
  p.geometry.points.clear();
  expect_input_error([&] { close_domain(p); }, "no points");
}

TEST(SolverInput, DomainClosingAddsArcAxisAndAir) {
  // The open boundary: a 96-chord semicircle of radius 5 x bounding radius marked with
  // c0 = nu0 / R0, axis segments joining the points on r = 0, and a background "air" region.
  cases::Problem p = square(cases::Symmetry::axisymmetric);
  p.outer = cases::OuterBoundary::open;
  p.geometry.points = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
  p.geometry.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  const cases::Problem closed = close_domain(p);
  const double radius = 5.0 * std::hypot(1.0, 0.5);
  ASSERT_EQ(closed.boundaries.size(), 1u);
  EXPECT_EQ(closed.boundaries[0].kind, cases::BoundaryKind::mixed);
  EXPECT_NEAR(closed.boundaries[0].c0, kNu0 / radius, 1e-9);
  EXPECT_EQ(closed.geometry.points.size(), 4u + kOuterArcSegments + 1);
  // 4 square sides + 96 chords + 2 axis segments (below and above the square).
  EXPECT_EQ(closed.geometry.segments.size(), 4u + kOuterArcSegments + 2);
  ASSERT_EQ(closed.geometry.regions.size(), 2u);
  EXPECT_EQ(closed.geometry.default_region, 1);
  EXPECT_EQ(closed.geometry.regions[1].name, "air");
  EXPECT_EQ(closed.materials[closed.regions[1].material].name, "air");
}

}  // namespace
}  // namespace rheomag::magnetostatics
