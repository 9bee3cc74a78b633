// solve_problem by nested iteration above SolveOptions::nested_above nodes (issue 35 point 1).
// Reference: the same problem solved on the same mesh from A = 0 (nested_above = 0). Both stop
// at Newton's relative residual of 1e-8, so lambda and dlambda/dI must agree to 1e-8 relative
// (the bound; the pot core measured 1e-12, test_nested_solve). The coarse levels are
// checked against size_scale: each has fewer nodes than the next, by at least 1.5 and at most
// 4 x 1.6 (a quarter where the sizes rule; less on small meshes, where the boundary points, the
// gaps' layers and the grading hold nodes that do not scale).

#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "core/error.hpp"
#include "magnetostatics/domain.hpp"
#include "magnetostatics/solve_problem.hpp"

// The bundled case carries a [valve] section of a later layer (as test_reference_valves).
const bool kValveSectionRegistered = rheomag::cases::register_case_section("valve") &&
                                     rheomag::cases::register_case_section("optimise");

namespace rheomag::magnetostatics {
namespace {

cases::Problem annular_valve() {
  return cases::read_case_file(std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml")
      .problem;
}

TEST(SolveProblemNested, CoarserMeshesHaveFewerNodesDownToATenthOfTheBound) {
  SolveOptions options;  // twice the default density: about 4.5e4 nodes
  options.mesh.size_scale = 0.5;
  options.nested_above = 20'000;
  auto [closed, mesh] = close_and_mesh(annular_valve(), options);
  const std::size_t fine = mesh.nodes.size();
  const auto coarser = coarser_meshes(closed, fine, options);
  ASSERT_FALSE(coarser.empty()) << fine << " nodes";
  std::size_t next = fine;
  for (auto level = coarser.rbegin(); level != coarser.rend(); ++level) {
    const double ratio = static_cast<double>(next) / static_cast<double>(level->nodes.size());
    std::cout << next << " -> " << level->nodes.size() << " nodes\n";
    EXPECT_GT(ratio, 1.5);
    EXPECT_LT(ratio, 4.0 * 1.6);
    next = level->nodes.size();
  }
  EXPECT_GE(static_cast<double>(coarser.front().nodes.size()), 0.1 * 20'000 / 1.6);
  options.nested_above = 0;
  EXPECT_TRUE(coarser_meshes(closed, fine, options).empty());
  options.nested_above = static_cast<long>(fine);
  EXPECT_TRUE(coarser_meshes(closed, fine, options).empty());
}

TEST(SolveProblemNested, GivesThePlainSolvesLambdaAndInductance) {
  // The reference valve at twice the default density (about 4.5e4 nodes), nested from 2e4.
  SolveOptions plain;
  plain.mesh.size_scale = 0.5;
  plain.nested_above = 0;
  SolveOptions nested = plain;
  nested.nested_above = 20'000;
  const SolveResult a = solve_problem(annular_valve(), plain);
  const SolveResult b = solve_problem(annular_valve(), nested);
  ASSERT_EQ(a.solver->mesh().nodes.size(), b.solver->mesh().nodes.size());
  const double lambda = a.solution.flux_linkage[0],
               inductance = a.solution.incremental_inductance[0];
  EXPECT_NEAR(b.solution.flux_linkage[0], lambda, 1e-8 * lambda);
  EXPECT_NEAR(b.solution.incremental_inductance[0], inductance, 1e-8 * inductance);
  // The fine Newton starts near the solution: fewer fine steps than from A = 0.
  EXPECT_LT(b.solution.newton.iterations, a.solution.newton.iterations);
  RecordProperty("plain_newton", a.solution.newton.iterations);
  RecordProperty("nested_newton", b.solution.newton.iterations);
}

TEST(SolveProblemNested, RefusesANonPositiveSizeScale) {
  SolveOptions options;
  options.mesh.size_scale = 0.0;
  EXPECT_THROW(close_and_mesh(annular_valve(), options), InputError);
}

}  // namespace
}  // namespace rheomag::magnetostatics
