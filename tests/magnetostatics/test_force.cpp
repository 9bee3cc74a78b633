// Force by the weighted Maxwell stress tensor (solve --integral REGION:force) against two
// independent references: the virtual work of the solver's own co-energy, and the exact mutual
// inductance of coaxial loops.

#include <gtest/gtest.h>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "magnetostatics/stress_tensor.hpp"
#include "tests/magnetostatics/coil_problem.hpp"
#include "tests/magnetostatics/steel.hpp"

namespace rheomag::magnetostatics {
namespace {

cases::Material air() {
  return {"air", 1.0, {}, 0.0, "vacuum"};
}

/// Region index of `name` in a problem.
int region_named(const cases::Problem& p, const std::string& name) {
  for (int r = 0; r < static_cast<int>(p.geometry.regions.size()); ++r)
    if (p.geometry.regions[r].name == name) return r;
  return -1;
}

/// Solenoid actuator: a coil (500 turns, r 6..10 mm, z -10..10 mm) and an AISI 1010 plunger
/// (r 0..4 mm, 20 mm long) whose lower end is at `z0`, in open space.
cases::Problem plunger_actuator(double z0, double current) {
  return test::rectangles_problem({{0.0, 4e-3, z0, z0 + 20e-3, "plunger", 1, 0.0, 0.3e-3},
                                   {6e-3, 10e-3, -10e-3, 10e-3, "coil", 0, 500.0, 0.6e-3}},
                                  {air(), test::aisi1010()}, current, cases::OuterBoundary::open,
                                  2);
}

TEST(Force, PlungerStressTensorMatchesCoenergyDerivative) {
  // Reference: virtual work at constant current, F_z = dW'/dz0, by the central difference of the
  // co-energies of two solves with the plunger moved by +-0.25 mm (each re-meshed). Tolerance
  // 1 % (issue 31; measured +0.25 %: the difference's truncation error and the re-meshing noise
  // of W' are in it).
  // flux density is partly into the knee of the curve).
  const double z0 = 2e-3, delta = 0.25e-3, current = 2.0;
  const SolveResult at = solve_problem(plunger_actuator(z0, current));
  const cases::Problem& closed = at.solver->problem();
  const StressTensorForce f =
      stress_tensor_force(*at.solver, at.solution, {region_named(closed, "plunger")});
  const double w_plus = solve_problem(plunger_actuator(z0 + delta, current)).results.coenergy;
  const double w_minus = solve_problem(plunger_actuator(z0 - delta, current)).results.coenergy;
  const double virtual_work = (w_plus - w_minus) / (2.0 * delta);
  std::printf("plunger: stress tensor F_z %.6g N, dW'/dz %.6g N (%+.3f %%), W' %.6g J\n",
              f.force[1], virtual_work, 100.0 * (f.force[1] / virtual_work - 1.0),
              at.results.coenergy);
  EXPECT_LT(virtual_work, 0.0);  // the coil pulls the plunger in (towards -z)
  EXPECT_NEAR(f.force[1], virtual_work, 0.01 * std::abs(virtual_work));
  EXPECT_EQ(f.force[0], 0.0);
}

/// Mutual inductance of two coaxial circular filaments of radii a, b, axial distance d [H]
/// (Maxwell; e.g. Smythe, Static and Dynamic Electricity, 7.10):
/// M = mu0 sqrt(a b) [(2/k - k) K(k) - (2/k) E(k)], k^2 = 4ab / ((a + b)^2 + d^2).
double filament_mutual_inductance(double a, double b, double d) {
  const double k = std::sqrt(4.0 * a * b / ((a + b) * (a + b) + d * d));
  return kMu0 * std::sqrt(a * b) *
         ((2.0 / k - k) * boost::math::ellint_1(k) - 2.0 / k * boost::math::ellint_2(k));
}

/// dM/dd of two filaments (central difference of the exact M, relative step 1e-5: truncation
/// ~1e-10, rounding ~1e-11).
double filament_mutual_gradient(double a, double b, double d) {
  const double h = 1e-5 * d;
  return (filament_mutual_inductance(a, b, d + h) - filament_mutual_inductance(a, b, d - h)) /
         (2.0 * h);
}

TEST(Force, CoaxialCoilsMatchExactMutualInductanceGradient) {
  // Two coaxial coils of 2 mm x 2 mm cross-section at mean radius 20 mm, 10 mm apart, in air,
  // in series (100 turns each, 1 A). In air the current density is uniform, so the force is
  // exactly F_z = I^2 N^2 <dM/dd> with <.> the average of the filament formula over both cross
  // sections (5 x 5 Gauss-Legendre points each: quadrature error < 1e-6 for this smooth
  // integrand). Tolerance 0.5 %: an allowance for the discretisation and for the asymptotic
  // open boundary at 5x the model's radius (measured +0.001 %).
  const double a = 20e-3, c = 2e-3, d = 10e-3, turns = 100.0, current = 1.0;
  cases::Problem p = test::rectangles_problem(
      {{a - c / 2, a + c / 2, -d / 2 - c / 2, -d / 2 + c / 2, "lower", 0, turns, 0.25e-3},
       {a - c / 2, a + c / 2, d / 2 - c / 2, d / 2 + c / 2, "upper", 0, turns, 0.25e-3}},
      {air()}, current, cases::OuterBoundary::open, 2);
  const SolveResult solved = solve_problem(p);
  const StressTensorForce f = stress_tensor_force(
      *solved.solver, solved.solution, {region_named(solved.solver->problem(), "upper")});

  static constexpr double kX[5] = {-0.906179845938664, -0.538469310105683, 0.0, 0.538469310105683,
                                   0.906179845938664};
  static constexpr double kW[5] = {0.236926885056189, 0.478628670499366, 0.568888888888889,
                                   0.478628670499366, 0.236926885056189};
  double gradient = 0.0;  // <dM/dd> over both cross-sections
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k)
        for (int l = 0; l < 5; ++l) {
          const double w = kW[i] * kW[j] * kW[k] * kW[l] / 16.0;
          const double r1 = a + 0.5 * c * kX[i], z1 = -d / 2 + 0.5 * c * kX[j];
          const double r2 = a + 0.5 * c * kX[k], z2 = d / 2 + 0.5 * c * kX[l];
          gradient += w * filament_mutual_gradient(r1, r2, z2 - z1);
        }
  const double expected = current * current * turns * turns * gradient;
  std::printf("coaxial coils: stress tensor F_z %.6g N, I^2 N^2 dM/dd %.6g N (%+.3f %%)\n",
              f.force[1], expected, 100.0 * (f.force[1] / expected - 1.0));
  EXPECT_LT(expected, 0.0);  // parallel currents attract
  EXPECT_NEAR(f.force[1], expected, 0.005 * std::abs(expected));
}

/// Planar rotor: an AISI 1010 bar (20 mm x 6 mm, turned by `theta` from x) between two
/// conductors at y = +-16 mm (+-400 ampere-turns along z), which give a field along x at the
/// centre; open boundary, depth 0.1 m.
cases::Problem planar_rotor(double theta, double current) {
  cases::Problem p =
      test::rectangles_problem({{-10e-3, 10e-3, 14e-3, 18e-3, "go", 0, 200.0, 0.8e-3},
                                {-10e-3, 10e-3, -18e-3, -14e-3, "return", 0, -200.0, 0.8e-3}},
                               {air(), test::aisi1010()}, current, cases::OuterBoundary::open, 2);
  p.symmetry = cases::Symmetry::planar;
  p.depth = 0.1;
  const int first = static_cast<int>(p.geometry.points.size());
  const double c = std::cos(theta), s = std::sin(theta);
  for (const auto& [x, y] :
       {std::pair{-10e-3, -3e-3}, {10e-3, -3e-3}, {10e-3, 3e-3}, {-10e-3, 3e-3}})
    p.geometry.points.push_back({c * x - s * y, s * x + c * y});
  for (int k = 0; k < 4; ++k) p.geometry.segments.push_back({first + k, first + (k + 1) % 4});
  mesh::RegionSeed seed;
  seed.seed = {0.0, 0.0};
  seed.name = "rotor";
  seed.mesh_size = 0.3e-3;
  p.geometry.regions.push_back(seed);
  p.regions.push_back({1, -1, 0.0});
  return p;
}

TEST(Force, PlanarRotorTorqueMatchesCoenergyDerivative) {
  // Reference: virtual work at constant current, torque = dW'/dtheta, by the central difference
  // of the co-energies of two solves with the rotor turned by +-0.5 degrees (re-meshed).
  // Tolerance 1 % (issue 31), as for the plunger.
  const double theta = 30.0 * std::numbers::pi / 180.0, delta = 0.5 * std::numbers::pi / 180.0;
  const double current = 2.0;
  const SolveResult at = solve_problem(planar_rotor(theta, current));
  const StressTensorForce f =
      stress_tensor_force(*at.solver, at.solution, {region_named(at.solver->problem(), "rotor")});
  const double w_plus = solve_problem(planar_rotor(theta + delta, current)).results.coenergy;
  const double w_minus = solve_problem(planar_rotor(theta - delta, current)).results.coenergy;
  const double virtual_work = (w_plus - w_minus) / (2.0 * delta);
  std::printf(
      "planar rotor: stress tensor torque %.6g N m, dW'/dtheta %.6g N m (%+.3f %%); "
      "net force (%.3g, %.3g) N\n",
      f.torque, virtual_work, 100.0 * (f.torque / virtual_work - 1.0), f.force[0], f.force[1]);
  EXPECT_LT(virtual_work, 0.0);  // the bar turns towards the field (theta -> 0)
  EXPECT_NEAR(f.torque, virtual_work, 0.01 * std::abs(virtual_work));
}

TEST(Force, SelectionTouchingIronIsRefusedByName) {
  // The stress tensor needs air around the body: a plunger resting on an iron stop is refused
  // naming both regions.
  cases::Problem p =
      test::rectangles_problem({{0.0, 4e-3, 0.0, 20e-3, "plunger", 1, 0.0, 0.0},
                                {6e-3, 10e-3, -10e-3, 10e-3, "coil", 0, 500.0, 0.0}},
                               {air(), test::aisi1010()}, 1.0, cases::OuterBoundary::open, 1);
  // The stop: below the plunger, sharing its bottom edge (points 0 and 1).
  const int first = static_cast<int>(p.geometry.points.size());
  p.geometry.points.push_back({0.0, -5e-3});
  p.geometry.points.push_back({4e-3, -5e-3});
  p.geometry.segments.push_back({0, first});
  p.geometry.segments.push_back({first, first + 1});
  p.geometry.segments.push_back({first + 1, 1});
  mesh::RegionSeed seed;
  seed.seed = {2e-3, -2.5e-3};
  seed.name = "stop";
  p.geometry.regions.push_back(seed);
  p.regions.push_back({1, -1, 0.0});
  const SolveResult solved = solve_problem(p);
  try {
    stress_tensor_force(*solved.solver, solved.solution,
                        {region_named(solved.solver->problem(), "plunger")});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'plunger'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'stop'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rheomag::magnetostatics
