// rheomag export: a case written as a FEMM .fem (case/femm_export) and read back. Field by field
// the read-back problem is the written one; solved, the .fem gives the TOML case's flux linkage
// within 0.5 % (the round-trip criterion; the meshes differ: the .fem's block sizes are
// the mean edges of rheomag's mesh, so the two are alike but not the same).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "case/femm_export.hpp"
#include "case/femm_import.hpp"
#include "core/error.hpp"
#include "magnetostatics/domain.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "tests/magnetostatics/femm_text.hpp"

// The bundled annular valve carries [valve]; in the program the valve layer registers it, and
// this test, which links only the layers below, registers it itself.
const bool kValveSectionRegistered = rheomag::cases::register_case_section("valve");

using namespace rheomag;
using namespace rheomag::magnetostatics;
using ::testing::HasSubstr;

namespace {

/// Solves a case and its exported .fem; returns the two flux linkages of circuit 0.
std::pair<double, double> round_trip(const cases::Problem& problem) {
  const SolveResult direct = solve_problem(problem);
  const std::string fem = cases::write_femm(close_domain(problem), {});
  const SolveResult again = solve_problem(cases::parse_femm(fem, "export.fem"));
  return {direct.results.circuits.at(0).flux_linkage, again.results.circuits.at(0).flux_linkage};
}

}  // namespace

// The pot core (nonlinear AISI 1010, 200 turns at 10 A, automatic A = 0 semicircle).
TEST(FemmExport, PotCoreRoundTrip) {
  const cases::Case c =
      cases::load_case(std::string(RHEOMAG_TEST_DATA) + "/pot_core_equivalent.toml");
  const auto [toml, fem] = round_trip(c.problem);
  EXPECT_GT(toml, 0.0);
  EXPECT_NEAR(fem, toml, 0.005 * toml);
}

// The bundled annular valve (template case, open boundary = FEMM mixed condition, MR-fluid gap
// meshed as finely through the .fem's block size).
TEST(FemmExport, AnnularValveRoundTrip) {
  const cases::Case c =
      cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml");
  const auto [toml, fem] = round_trip(c.problem);
  EXPECT_GT(toml, 0.0);
  EXPECT_NEAR(fem, toml, 0.005 * toml);
}

// Everything the writer puts in the file comes back: geometry, boundary kinds and values,
// B-H tables to the last digit, circuits and signed turns, magnets, point conditions.
TEST(FemmExport, FieldsReadBack) {
  cases::Case c = cases::load_case(std::string(RHEOMAG_TEST_DATA) + "/pot_core_equivalent.toml");
  cases::Problem p = close_domain(c.problem);
  p.regions[1].turns = -200;
  p.point_conditions.push_back({"wire", 3, false, 0.0, 2.5});
  const cases::Problem q = cases::parse_femm(cases::write_femm(p, {}), "back.fem");
  ASSERT_EQ(q.geometry.points.size(), p.geometry.points.size());
  for (std::size_t i = 0; i < p.geometry.points.size(); ++i) {
    EXPECT_EQ(q.geometry.points[i].r, p.geometry.points[i].r);
    EXPECT_EQ(q.geometry.points[i].z, p.geometry.points[i].z);
  }
  ASSERT_EQ(q.geometry.segments.size(), p.geometry.segments.size());
  for (std::size_t i = 0; i < p.geometry.segments.size(); ++i)
    EXPECT_EQ(q.geometry.segments[i].boundary, p.geometry.segments[i].boundary);
  ASSERT_EQ(q.boundaries.size(), p.boundaries.size());
  EXPECT_EQ(q.boundaries[0].kind, p.boundaries[0].kind);
  ASSERT_EQ(q.circuits.size(), 1u);
  EXPECT_EQ(q.circuits[0].current, p.circuits[0].current);
  bool found_coil = false, found_iron = false;
  for (std::size_t r = 0; r < q.regions.size(); ++r) {
    const cases::Material& m = q.materials[q.regions[r].material];
    if (q.regions[r].circuit == 0) {
      found_coil = true;
      EXPECT_EQ(q.regions[r].turns, -200);
    }
    if (m.name == "AISI 1010" && !found_iron) {
      found_iron = true;
      const cases::Material& original = p.materials[p.regions[0].material];
      ASSERT_EQ(m.bh.size(), original.bh.size());
      for (std::size_t k = 0; k < m.bh.size(); ++k) {
        EXPECT_EQ(m.bh[k].b, original.bh[k].b);
        EXPECT_EQ(m.bh[k].h, original.bh[k].h);
      }
    }
  }
  EXPECT_TRUE(found_coil);
  EXPECT_TRUE(found_iron);
  ASSERT_EQ(q.point_conditions.size(), 1u);
  EXPECT_EQ(q.point_conditions[0].point, 3);
  EXPECT_EQ(q.point_conditions[0].current, 2.5);
}

// What a .fem cannot hold is refused by name.
TEST(FemmExport, RefusesFractionalTurns) {
  cases::Case c = cases::load_case(std::string(RHEOMAG_TEST_DATA) + "/pot_core_equivalent.toml");
  cases::Problem p = close_domain(c.problem);
  p.regions[1].turns = 200.5;
  try {
    cases::write_femm(p, {});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("region 'coil' has 200.5 turns"));
  }
}

// A .fem in inches with a magnet direction expression (FEMM evaluates x, y in the file's unit)
// is written back in inches, and the read-back magnet gives the same exact field
// B = mu0 mu_r H_c m (the box's closed form, see test_femm_models).
TEST(FemmExport, MagnetExpressionKeepsItsLengthUnit) {
  rheomag::testing::FemText f;
  f.blocks = {rheomag::testing::fem_block("magnet", 1.05, 9e5)};
  f.points = {"0 0 0 0", "2 0 0 0", "2 1 0 0", "0 1 0 0"};
  f.segments = {"0 1 -1 0 0 0", "1 2 -1 0 0 0", "2 3 -1 0 0 0", "3 0 -1 0 0 0"};
  f.labels = {"1 0.5 1 0.2 0 0 0 1 0 \"30 + 0 * (x - 1)\""};
  std::string text = f.str();
  text.replace(text.find("meters"), 6, "inches");
  const cases::Problem p = cases::parse_femm(text, "inches.fem");
  const std::string written = cases::write_femm(close_domain(p), {});
  EXPECT_THAT(written, HasSubstr("[LengthUnits] =  inches"));
  const cases::Problem q = cases::parse_femm(written, "back.fem");
  EXPECT_EQ(q.regions[0].magnetisation.expression, "30 + 0 * (x - 1)");
  EXPECT_DOUBLE_EQ(q.geometry.points[2].r, 2 * 0.0254);
  const SolveResult s = solve_problem(q);
  std::array<double, 2> b{};
  ASSERT_TRUE(flux_density_at(*s.solver, s.solution, {0.01, 0.01}, -1, b));
  const double magnitude = 4e-7 * std::numbers::pi * 1.05 * 9e5;
  EXPECT_NEAR(b[0], magnitude * std::sqrt(3.0) / 2, 1e-9 * magnitude);
  EXPECT_NEAR(b[1], magnitude / 2, 1e-9 * magnitude);
}
