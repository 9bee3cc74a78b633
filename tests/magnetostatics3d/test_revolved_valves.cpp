// Validation: the bundled valves revolved to 3D (no features: an exact wedge model) reproduce
// the 2D axisymmetric solution. Reference: rheomag's 2D P2 solver on the same case (itself
// validated against FEMM and analytic circuits, docs/validation.md). Tolerance: 1 % on every
// gap's |B| average (both meridian-area weighted) and on the flux linkage, the target.
// The 3D model uses tangential A = 0 on the outer sphere where 2D uses its open condition: the
// difference is below 1e-4 for these cases (docs/magnetostatics3d.md).

#include <gtest/gtest.h>

#include <string>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "magnetostatics3d/solve3d.hpp"

namespace rheomag::magnetostatics3d {
namespace {

// The bundled cases also hold sections of later layers (not linked into this test).
const bool kLaterSectionsRegistered = cases::register_case_section("valve") &&
                                      cases::register_case_section("damper") &&
                                      cases::register_case_section("fluid");

void expect_3d_matches_2d(const std::string& name) {
  const cases::Case c = cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/" + name);
  const magnetostatics::SolveResult two = magnetostatics::solve_problem(c.problem);
  const Solve3dResult three = solve_problem_3d(c.problem);
  EXPECT_EQ(three.results.part, ModelPart::wedge);
  ASSERT_EQ(three.results.gaps.size(), two.results.gaps.size());
  ASSERT_FALSE(two.results.gaps.empty());
  for (std::size_t g = 0; g < two.results.gaps.size(); ++g) {
    EXPECT_EQ(three.results.gaps[g].name, two.results.gaps[g].name);
    EXPECT_NEAR(three.results.gaps[g].b.average / two.results.gaps[g].b.average, 1.0, 0.01)
        << name << " gap " << two.results.gaps[g].name;
    // An axisymmetric body: the same average in every sector.
    for (double b : three.results.gaps[g].b_avg_theta)
      EXPECT_DOUBLE_EQ(b, three.results.gaps[g].b.average);
  }
  ASSERT_EQ(three.results.circuits.size(), 1u);
  EXPECT_NEAR(three.results.circuits[0].flux_linkage / two.results.circuits[0].flux_linkage, 1.0,
              0.01)
      << name;
  EXPECT_GT(three.results.newton_iterations, 1);  // nonlinear steel: Newton did work
}

TEST(RevolvedValves, AnnularValveMatches2dWithinOnePercent) {
  expect_3d_matches_2d("annular_valve.toml");
}

TEST(RevolvedValves, MeanderingValveMatches2dWithinOnePercent) {
  expect_3d_matches_2d("meandering_valve.toml");
}

}  // namespace
}  // namespace rheomag::magnetostatics3d
