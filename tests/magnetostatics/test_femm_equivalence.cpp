// A hand-written FEMM model (tests/data/pot_core.fem: axisymmetric AISI 1010 pot core, 200-turn
// coil at 10 A, 2 mm air gap, lid, A = 0 on a 150 mm semicircle) and the equivalent rheomag case
// (tests/data/pot_core_equivalent.toml, automatic Dirichlet semicircle of the same radius) give
// the same flux linkage and gap flux density. The PSLGs differ (the .fem splits nothing, the
// TOML reader merges and splits shared edges) and so do the meshes; both are P2 at 1 mm
// (0.5 mm in the gap), so the discretisation difference is far below the 0.5 % tolerance
// (measured: 1e-6 relative). The iron is driven into its knee (Newton takes ~10 steps).

#include <gtest/gtest.h>

#include <array>
#include <string>

#include "case/case_file.hpp"
#include "magnetostatics/solve_problem.hpp"

using namespace rheomag::magnetostatics;
using namespace rheomag::cases;

TEST(FemmEquivalence, FemFileAndTomlCaseAgree) {
  const std::string data = RHEOMAG_TEST_DATA;
  const Case fem = load_case(data + "/pot_core.fem");
  const Case toml = load_case(data + "/pot_core_equivalent.toml");
  const SolveResult a = solve_problem(fem.problem);
  const SolveResult b = solve_problem(toml.problem);
  ASSERT_EQ(a.results.circuits.size(), 1u);
  ASSERT_EQ(b.results.circuits.size(), 1u);
  const double lambda_fem = a.results.circuits[0].flux_linkage;
  const double lambda_toml = b.results.circuits[0].flux_linkage;
  EXPECT_GT(lambda_fem, 0.0);
  EXPECT_NEAR(lambda_fem, lambda_toml, 0.005 * lambda_toml);
  EXPECT_EQ(a.results.circuits[0].turns, 200.0);
  // |B| in the middle of the gap over the post (r = 5 mm, z = 19 mm).
  std::array<double, 2> ba{}, bb{};
  ASSERT_TRUE(flux_density_at(*a.solver, a.solution, {5e-3, 19e-3}, -1, ba));
  ASSERT_TRUE(flux_density_at(*b.solver, b.solution, {5e-3, 19e-3}, -1, bb));
  EXPECT_GT(bb[1], 0.5);  // the post's flux crosses the gap: well into the iron's knee
  EXPECT_NEAR(ba[1], bb[1], 0.005 * bb[1]);
  EXPECT_NEAR(ba[0], bb[0], 0.005 * std::abs(bb[1]));
  // Nonlinear: Newton needs several steps for both.
  EXPECT_GE(a.results.newton_iterations, 4);
  EXPECT_GE(b.results.newton_iterations, 4);
}
