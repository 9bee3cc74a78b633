// Block and line integrals (solve --integral, --line): each checked against a quantity the solver
// computes another way, and the refusals of bad requests.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "magnetostatics/block_integrals.hpp"
#include "magnetostatics/line_integral.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "tests/magnetostatics/coil_problem.hpp"
#include "tests/magnetostatics/steel.hpp"

namespace rheomag::magnetostatics {
namespace {

/// A coil (200 turns, 3 A, r 10..14 mm, z -5..5 mm) around an AISI 1010 core (r 0..8 mm), A = 0
/// on the outer boundary (no exterior energy term), P2.
SolveResult coil_with_core() {
  return solve_problem(
      test::rectangles_problem({{0.0, 8e-3, -10e-3, 10e-3, "core", 1, 0.0, 0.0},
                                {10e-3, 14e-3, -5e-3, 5e-3, "coil", 0, 200.0, 0.0}},
                               {{"air", 1.0, {}, 0.0, "vacuum"}, test::aisi1010()}, 3.0,
                               cases::OuterBoundary::dirichlet, 2));
}

double value(const BlockIntegral& b, const std::string& component) {
  for (const IntegralComponent& c : b.components)
    if (c.name == component) return c.value;
  ADD_FAILURE() << "no component " << component;
  return 0.0;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BlockIntegrals, AgreeWithTheSolversOwnTotals) {
  // References (two ways of the same number, relative 1e-9): the region energies add up to the
  // model's (Dirichlet boundary: no exterior term); A.J over the coil is I lambda (lambda =
  // sum (N/S) integral A dV); the coil's mean flux times its turns is lambda; the rectangle's
  // area and volume are exact (2 pi r_mean S).
  const SolveResult s = coil_with_core();
  const std::vector<BlockIntegral> b =
      block_integrals(*s.solver, s.solution,
                      {"core+coil+air:energy", "core+coil+air:coenergy", "coil:a_dot_j",
                       "coil:flux", "coil:area", "coil:volume", "core:average_b"});
  EXPECT_NEAR(value(b[0], "energy"), s.results.energy, 1e-9 * s.results.energy);
  EXPECT_NEAR(value(b[1], "coenergy"), s.results.coenergy, 1e-9 * s.results.coenergy);
  const double lambda = s.results.circuits[0].flux_linkage;
  EXPECT_NEAR(value(b[2], "a_dot_j"), 3.0 * lambda, 1e-9 * std::abs(3.0 * lambda));
  EXPECT_NEAR(200.0 * value(b[3], "flux"), lambda, 1e-9 * std::abs(lambda));
  EXPECT_NEAR(value(b[4], "area"), 4e-3 * 10e-3, 1e-12);
  EXPECT_NEAR(value(b[5], "volume"), 2.0 * std::numbers::pi * 12e-3 * 4e-5, 1e-15);
  EXPECT_GT(value(b[6], "b_z"), 0.1);  // the coil magnetises the core along z
  EXPECT_LT(std::abs(value(b[6], "b_r")), 1e-3 * value(b[6], "b_z"));  // symmetric about z = 0
  EXPECT_EQ(b[0].femm, "mo_blockintegral(2)");
  EXPECT_EQ(b[1].femm, "mo_blockintegral(17)");
}

TEST(LineIntegral, FluxFromPotentialMatchesTheSampledNormalField) {
  // A radial line across the core's mid-plane (z = 0): the flux 2 pi (r2 A2 - r1 A1) from A
  // against the trapezoidal integral of B_n 2 pi r ds over 20001 samples. Tolerance 5e-4: B_n
  // = B_z jumps by mu_r at the core's surface, so the trapezoid rule's error is O(h) there
  // (measured 2e-3 with 2001 samples, 2e-4 with 20001).
  const SolveResult s = coil_with_core();
  const LineField line = line_field(*s.solver, s.solution, "0,0:0.02,0", 20001);
  double sampled = 0.0;
  for (std::size_t k = 1; k < line.samples.size(); ++k) {
    const LineSample &p = line.samples[k - 1], &q = line.samples[k];
    sampled += 0.5 * (q.s - p.s) * 2.0 * std::numbers::pi * (p.r * p.b_n + q.r * q.b_n);
  }
  std::printf("flux through the mid-plane line: from A %.6g Wb, sampled %.6g Wb\n",
              line.normal_flux, sampled);
  EXPECT_NEAR(line.normal_flux, sampled, 5e-4 * std::abs(sampled));
  // Along +r the normal is +z: the core's flux is upwards, B_n = B_z > 0 at the axis.
  EXPECT_GT(line.samples.front().b_n, 0.1);
  // B_t = B_r vanishes at the centre by symmetry, up to the mesh's asymmetry about z = 0.
  EXPECT_LT(std::abs(line.samples.front().b_t), 2e-3 * line.samples.front().b_n);
}

TEST(BlockIntegrals, BadRequestsAreRefusedWithWhatExists) {
  const SolveResult s = coil_with_core();
  const std::string unknown =
      error_of([&] { block_integrals(*s.solver, s.solution, {"plunger:force"}); });
  EXPECT_NE(unknown.find("no region named 'plunger'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("core, coil"), std::string::npos) << unknown;
  const std::string kind =
      error_of([&] { block_integrals(*s.solver, s.solution, {"core:bogus"}); });
  EXPECT_NE(kind.find("\"coenergy\""), std::string::npos) << kind;
  const std::string torque =
      error_of([&] { block_integrals(*s.solver, s.solution, {"core:torque"}); });
  EXPECT_NE(torque.find("planar"), std::string::npos) << torque;
  const std::string outside = error_of([&] { line_field(*s.solver, s.solution, "0,0:10,0", 11); });
  EXPECT_NE(outside.find("outside the model"), std::string::npos) << outside;
  EXPECT_NE(outside.find("the model spans 0.."), std::string::npos) << outside;
}

}  // namespace
}  // namespace rheomag::magnetostatics
