// Non-axisymmetric features on a small annular valve (tests/data/magnetostatics3d), half models.
// Reference for the field changes: the ideal-steel magnetic circuit, where the pole surfaces are
// magnetic equipotentials, so the gap flux density under each point of a pole is
// B = mu0 U / g_local (U the magnetic potential drop across the gap, the same everywhere).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "case/case_file.hpp"
#include "case/toml_section.hpp"
#include "core/error.hpp"
#include "magnetostatics3d/solve3d.hpp"

namespace rheomag::magnetostatics3d {
namespace {

constexpr double kPi = std::numbers::pi;

cases::Case small_valve(const std::string& features) {
  const std::string path = std::string(RHEOMAG_TEST_DATA) + "/magnetostatics3d/small_valve.toml";
  return cases::parse_case(cases::read_input_file(path) + features, path);
}

/// Coarse settings: one tetrahedron across the 2 mm gaps, 10-degree facets (the profile shapes
/// below agree with a model twice as fine to 2 %; docs/magnetostatics3d.md).
Solve3dOptions coarse() {
  Solve3dOptions o;
  o.gap_layers = 1;
  o.region_fraction = 0.5;
  o.facet_angle = 10.0 * kPi / 180.0;
  return o;
}

// Eccentric core: everything inside the gap moves 0.4 mm towards phi = 0, so the 2 mm gaps are
// g(phi) = 2 - 0.4 cos(phi) mm. Ideal steel: B(phi) g(phi) is constant; tolerance 5 % per
// 10-degree sector (finite steel permeability and fringing at the pole ends).
TEST(Features, EccentricCoreGivesGapFieldInverseToTheLocalGap) {
  const cases::Case c = small_valve(
      "\n[[feature]]\nkind = \"eccentricity\"\ngap = \"gap_top\"\noffset = 0.4\nangle = 0\n");
  const Solve3dResult s = solve_problem_3d(c.problem, read_features(c), coarse());
  EXPECT_EQ(s.results.part, ModelPart::half);
  for (const GapResult3d& g : s.results.gaps) {
    double mean = 0.0;
    std::array<double, kThetaSectors> product{};
    for (int k = 0; k < kThetaSectors; ++k) {
      const double phi = (k + 0.5) * 2 * kPi / kThetaSectors;
      product[k] = g.b_avg_theta[k] * (2.0 - 0.4 * std::cos(phi));
      mean += product[k] / kThetaSectors;
    }
    for (int k = 0; k < kThetaSectors; ++k)
      EXPECT_NEAR(product[k] / mean, 1.0, 0.05) << g.name << k;
    // Narrow side / wide side: (2.4 / 1.6) = 1.5 for ideal steel.
    EXPECT_NEAR(g.b_avg_theta[0] / g.b_avg_theta[kThetaSectors / 2], 1.5, 0.075) << g.name;
  }
}

// Lead slot 2 mm wide, 1.5 mm deep in the core's 8 mm outer radius at phi = 0: it spans
// +-7.2 degrees, 72 % of the first 10-degree sector, and there the gap grows from 2 to 3.5 mm.
// Ideal steel: that sector's average falls to 0.72 x 2/3.5 + 0.28 = 0.69 of the rest (a lower
// bound: fringing into the slot raises it); sectors away from the slot keep their field (5 %).
TEST(Features, LeadSlotLowersTheFieldOverTheSlotOnly) {
  const cases::Case plain = small_valve("");
  const cases::Case slotted = small_valve(
      "\n[[feature]]\nkind = \"lead_slot\"\nregion = \"core\"\nwidth = 2.0\ndepth = 1.5\n");
  const Solve3dResult a = solve_problem_3d(plain.problem, {}, coarse());
  const Solve3dResult b = solve_problem_3d(slotted.problem, read_features(slotted), coarse());
  ASSERT_EQ(a.results.gaps.size(), b.results.gaps.size());
  for (std::size_t g = 0; g < a.results.gaps.size(); ++g) {
    const auto& plain_theta = a.results.gaps[g].b_avg_theta;
    const auto& slot_theta = b.results.gaps[g].b_avg_theta;
    const double ratio = slot_theta[0] / plain_theta[0];
    EXPECT_GT(ratio, 0.69 - 0.03);
    EXPECT_LT(ratio, 0.85);
    EXPECT_NEAR(slot_theta[35] / plain_theta[35], ratio, 0.1);  // mirror image of sector 0
    for (int k = 6; k <= 30; ++k) EXPECT_NEAR(slot_theta[k] / plain_theta[k], 1.0, 0.07) << k;
  }
}

std::string bolt_holes(const std::string& material) {
  std::string text;
  for (int angle : {45, 135, 225, 315}) {
    text +=
        "\n[[feature]]\nkind = \"hole\"\nregion = \"disk\"\nradius = 0.75\nposition = 11.5\n"
        "angle = " +
        std::to_string(angle) + material + "\n";
  }
  return text;
}

// Four axial bolt holes (radius 0.75 mm at r = 11.5 mm) through the 3 mm flux-return ring
// (r = 10..13 mm) at 45, 135, 225 and 315 degrees: a mirror-symmetric ring, so a half model.
// Reference: the same mesh with the holes filled by the ring's steel (identical tetrahedra, so
// the difference is the holes' alone). Physics: the flux returning axially through the ring
// must pass around each hole, so the gap field dips at the holes' angles; the whole-ring
// cross-section A falls by f = 4 pi a^2 / A (3.3 %), which bounds the fall of the gap flux from
// above (it would equal f only if the ring alone set the reluctance; the 2 mm gaps dominate).
TEST(Features, BoltHolesLowerTheGapFieldAtTheirAnglesByLessThanTheSteelTheyRemove) {
  const cases::Case steel = small_valve(bolt_holes("\nmaterial = \"AISI 1010\""));
  const cases::Case holes = small_valve(bolt_holes(""));
  Solve3dOptions options = swept_options();
  options.gap_layers = 1;
  options.region_fraction = 0.5;
  const Solve3dResult a = solve_problem_3d(steel.problem, read_features(steel), options);
  const Solve3dResult b = solve_problem_3d(holes.problem, read_features(holes), options);
  EXPECT_EQ(b.results.part, ModelPart::half);
  ASSERT_EQ(a.results.tetrahedra, b.results.tetrahedra);
  std::printf("bolt holes: %d tetrahedra, %d dofs, %d / %d Newton steps, %.1f + %.1f s\n",
              b.results.tetrahedra, b.results.dofs, a.results.newton_iterations,
              b.results.newton_iterations, a.results.seconds, b.results.seconds);
  const double f = 4 * 0.75 * 0.75 / (13.0 * 13.0 - 10.0 * 10.0);
  for (std::size_t g = 0; g < a.results.gaps.size(); ++g) {
    const double mean = b.results.gaps[g].b.average / a.results.gaps[g].b.average;
    EXPECT_LT(mean, 1.0) << a.results.gaps[g].name;
    EXPECT_GT(mean, 1.0 - f) << a.results.gaps[g].name;
    std::array<double, kThetaSectors> ratio{};
    for (int k = 0; k < kThetaSectors; ++k)
      ratio[k] = b.results.gaps[g].b_avg_theta[k] / a.results.gaps[g].b_avg_theta[k];
    std::printf("%s: holes / steel-filled mean %.5f, per sector", a.results.gaps[g].name.c_str(),
                mean);
    for (double x : ratio) std::printf(" %.4f", x);
    std::printf("\n");
    // The sectors holding a hole's axis (40-50, 130-140, ... degrees) fall most; the sectors
    // midway between holes (0, 90, 180, 270 degrees) least.
    const int weakest =
        static_cast<int>(std::min_element(ratio.begin(), ratio.end()) - ratio.begin());
    EXPECT_EQ((weakest % 9), 4) << a.results.gaps[g].name << " weakest sector " << weakest;
    for (int hole : {4, 13, 22, 31}) {
      for (int midway : {0, 9, 18, 27}) EXPECT_LT(ratio[hole], ratio[midway]) << hole << midway;
    }
  }
}

void expect_input_error(const std::string& features, const std::string& expected) {
  const cases::Case c = small_valve(features);
  try {
    solve_problem_3d(c.problem, read_features(c), coarse());
    FAIL() << "no InputError for " << features;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

TEST(Features, BadFeaturesAreInputErrorsNamingTheFeature) {
  expect_input_error(
      "\n[[feature]]\nkind = \"slot\"\n",
      "feature[1].kind: expected \"lead_slot\", \"hole\", \"port\" or \"eccentricity\"");
  expect_input_error(
      "\n[[feature]]\nkind = \"hole\"\nregion = \"shaft\"\nradius = 1\nposition = 5\n",
      "region 'shaft' does not exist");
  expect_input_error(
      "\n[[feature]]\nkind = \"hole\"\nregion = \"disk\"\nradius = 1\nposition = 30\n",
      "feature[1] (hole): the cut lies partly outside region 'disk'");
  expect_input_error(
      "\n[[feature]]\nkind = \"hole\"\nregion = \"disk\"\nradius = 1\nposition = 11.5\n"
      "[[feature]]\nkind = \"hole\"\nregion = \"disk\"\nradius = 1\nposition = 11.5\n",
      "feature[2] (hole): overlaps");
  expect_input_error(
      "\n[[feature]]\nkind = \"lead_slot\"\nregion = \"core\"\nwidth = 1\ndepth = 20\n",
      "feature[1] (lead_slot): the cut lies partly outside region 'core'");
  expect_input_error("\n[[feature]]\nkind = \"eccentricity\"\ngap = \"gap_top\"\noffset = 3\n",
                     "offset must be smaller than the gap width");
}

// A material with mu_r along r and z (a laminated core) leaves mu_r along phi unstated when
// revolved: refused by name before meshing.
TEST(Features, AnisotropicMaterialIsRefusedByName) {
  cases::Case c = small_valve("");
  cases::Material& core = c.problem.materials.at(c.problem.regions.at(0).material);
  core.bh.clear();
  core.mu_r_axes = std::array{500.0, 5.0};
  try {
    solve_problem_3d(c.problem, read_features(c), coarse());
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("material '" + core.name +
                                         "' is anisotropic (mu_r along r and z differ), which "
                                         "the 3D solver does not support"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace rheomag::magnetostatics3d
