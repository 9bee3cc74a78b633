// Every bad-input class of a TOML case gives one InputError naming the file, the line or key
// and what was expected (issue 2, "Bad input"). Each test mutates one thing of a valid case.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <regex>
#include <string>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "core/error.hpp"

using namespace rheomag::cases;
using ::testing::HasSubstr;

namespace {

// A valid general case: a steel block, a coil beside it, a fluid gap above. Units mm.
const std::string valid = R"([case]
units = "mm"

[[circuit]]
name = "coil"
current = 1.0

[[region]]
name = "core"
material = "AISI 1010"
points = [[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]]

[[region]]
name = "winding"
material = "Copper"
coil = { circuit = "coil", turns = 100 }
points = [[10, 0], [20, 0], [20, 10], [10, 10], [10, 0]]

[[region]]
name = "gap"
material = "MRF-132DG"
gap = "radial"
points = [[0, 10], [20, 10], [20, 11], [0, 11], [0, 10]]
)";

/// The InputError message of parsing `text`, or "no error".
std::string error_of(const std::string& text) {
  try {
    parse_case(text, "bad.toml");
  } catch (const rheomag::InputError& e) {
    return e.what();
  }
  return "no error";
}

/// `valid` with the first occurrence of `from` replaced by `to`.
std::string with(const std::string& from, const std::string& to) {
  std::string text = valid;
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST(CaseErrors, ValidCaseParses) {
  EXPECT_EQ(error_of(valid), "no error");
}

TEST(CaseErrors, UnknownMaterialSuggestsTheClosest) {
  const std::string message = error_of(with("\"AISI 1010\"", "\"AISI 1011\""));
  EXPECT_THAT(message, HasSubstr("bad.toml:10: region[1].material: region 'core'"));
  EXPECT_THAT(message, HasSubstr("unknown material 'AISI 1011'; did you mean 'AISI 1010'?"));
}

TEST(CaseErrors, RegionWithoutMaterial) {
  EXPECT_THAT(error_of(with("material = \"Copper\"\n", "")),
              HasSubstr("region[2].material: region 'winding' has no material"));
}

TEST(CaseErrors, OpenPolyline) {
  EXPECT_THAT(error_of(with("[0, 10], [0, 0]]", "[0, 10]]")),
              HasSubstr("the outline of region 'core' is open: its last point must repeat the "
                        "first point"));
}

TEST(CaseErrors, SelfIntersectingPolyline) {
  // A bow tie: (0,0) (10,0) (0,10) (10,10).
  EXPECT_THAT(error_of(with("[[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]]",
                            "[[0, 0], [10, 0], [0, 10], [10, 10], [0, 0]]")),
              HasSubstr("region 'core': outline intersects itself"));
}

TEST(CaseErrors, OverlappingRegions) {
  // The winding moved 2 mm left into the core.
  EXPECT_THAT(error_of(with("[[10, 0], [20, 0], [20, 10], [10, 10], [10, 0]]",
                            "[[8, 0], [20, 0], [20, 10], [8, 10], [8, 0]]")),
              HasSubstr("region 'winding' overlaps region 'core'"));
  // A region entirely inside another (no crossing edges).
  EXPECT_THAT(error_of(valid + "[[region]]\nname = \"inner\"\nmaterial = \"Air\"\n"
                               "points = [[2, 2], [4, 2], [4, 4], [2, 2]]\n"),
              HasSubstr("region 'inner' overlaps region 'core'"));
  // Identical outlines.
  EXPECT_THAT(error_of(valid + "[[region]]\nname = \"twin\"\nmaterial = \"Air\"\n"
                               "points = [[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]]\n"),
              HasSubstr("region 'twin' overlaps region 'core'"));
}

TEST(CaseErrors, ZeroOrNegativeTurns) {
  EXPECT_THAT(error_of(with("turns = 100", "turns = 0")),
              HasSubstr("region[2].coil.turns: expected a whole number in [1, 1000000000], got 0"));
  EXPECT_THAT(
      error_of(with("turns = 100", "turns = -5")),
      HasSubstr("region[2].coil.turns: expected a whole number in [1, 1000000000], got -5"));
}

TEST(CaseErrors, ZeroOrNegativeDimensionsAndGaps) {
  const std::string base =
      "[case]\nunits = \"mm\"\n[[circuit]]\nname = \"coil\"\n"
      "[geometry]\ntemplate = \"annular_valve\"\n";
  EXPECT_THAT(error_of(base + "gap_width = 0\n"),
              HasSubstr("bad.toml:7: geometry.gap_width: expected a positive number, got 0"));
  EXPECT_THAT(error_of(base + "pole_length = -2\n"),
              HasSubstr("geometry.pole_length: expected a positive number, got -2"));
  EXPECT_THAT(error_of(base + "neck_radius = 30\n"), HasSubstr("inconsistent dimensions"));
  EXPECT_THAT(error_of(with("[[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]]",
                            "[[0, 0], [10, 0], [10, 0], [0, 0], [0, 0]]")),
              HasSubstr("repeated point"));
  EXPECT_THAT(error_of(with("name = \"core\"\n", "name = \"core\"\nmesh_size = -1\n")),
              HasSubstr("region[1].mesh_size: expected a positive number, got -1"));
}

TEST(CaseErrors, BhTableNotMonotoneOrTooShort) {
  const std::string inline_material =
      "[[material]]\nname = \"soft\"\nbh = [[0, 0], [1.0, 100], [0.9, 200]]\n";
  EXPECT_THAT(error_of(with("\"AISI 1010\"", "\"soft\"") + inline_material),
              HasSubstr("material[1].bh: B-H table is not monotone at point 3"));
  const std::string short_material = "[[material]]\nname = \"soft\"\nbh = [[1.0, 100]]\n";
  EXPECT_THAT(error_of(with("\"AISI 1010\"", "\"soft\"") + short_material),
              HasSubstr("a B-H table needs at least 2 points"));
}

// A laminated core as an inline material: mu_r along r and z (solved in FemmAnisotropic.*).
TEST(CaseErrors, AnisotropicMaterialTakesTwoPermeabilities) {
  const std::string soft = with("\"AISI 1010\"", "\"soft\"");
  const Problem p =
      parse_case(soft + "[[material]]\nname = \"soft\"\nmu_r_axes = [160.2, 4.9]\n", "a.toml")
          .problem;
  bool found = false;
  for (const Material& m : p.materials) {
    if (m.name != "soft") continue;
    found = true;
    ASSERT_TRUE(m.mu_r_axes.has_value());
    EXPECT_EQ(*m.mu_r_axes, (std::array<double, 2>{160.2, 4.9}));
    EXPECT_EQ(m.mu_r, 160.2);
  }
  EXPECT_TRUE(found);
  EXPECT_THAT(error_of(soft + "[[material]]\nname = \"soft\"\nmu_r_axes = [160.2]\n"),
              HasSubstr("material[1].mu_r_axes: expected 2 numbers, mu_r along r (x) and along z "
                        "(y); got 1"));
  EXPECT_THAT(error_of(soft + "[[material]]\nname = \"soft\"\nmu_r_axes = [160.2, 0]\n"),
              HasSubstr("material[1].mu_r_axes: item 2"));
  EXPECT_THAT(error_of(soft + "[[material]]\nname = \"soft\"\nmu_r = 3\nmu_r_axes = [1, 2]\n"),
              HasSubstr("give one of mu_r, mu_r_axes (linear, anisotropic) or bh"));
}

TEST(CaseErrors, UnknownKeysNameTheLineAndTheClosestKey) {
  EXPECT_THAT(error_of(with("name = \"core\"\n", "name = \"core\"\nmesh_sise = 1\n")),
              HasSubstr("bad.toml:10: unknown key 'region[1].mesh_sise'; did you mean "
                        "'region[1].mesh_size'?"));
  EXPECT_THAT(error_of("[solvr]\norder = 2\n" + valid),
              HasSubstr("bad.toml:1: unknown key 'solvr'; did you mean 'solver'?"));
  EXPECT_THAT(error_of(with("units = \"mm\"", "units = \"mm\"\nunit = 1")),
              HasSubstr("unknown key 'case.unit'; did you mean 'case.units'?"));
}

TEST(CaseErrors, NanOrInfAnywhere) {
  EXPECT_THAT(error_of(with("current = 1.0", "current = nan")),
              HasSubstr("bad.toml:6: circuit[1].current: expected a finite number, got nan"));
  EXPECT_THAT(error_of(with("[20, 10], [10, 10]", "[20, inf], [10, 10]")),
              HasSubstr("region[2].points: point 3: expected finite numbers"));
  EXPECT_THAT(error_of(with("turns = 100", "turns = -inf")), HasSubstr("expected a finite number"));
}

TEST(CaseErrors, OtherInputMistakes) {
  EXPECT_THAT(error_of(with("circuit = \"coil\", turns", "circuit = \"coils\", turns")),
              HasSubstr("unknown circuit 'coils'"));
  EXPECT_THAT(error_of("[geometry]\ntemplate = \"anular_valve\"\n"),
              HasSubstr("unknown template 'anular_valve'; did you mean 'annular_valve'?"));
  EXPECT_THAT(error_of(with("units = \"mm\"", "units = \"inch\"")),
              HasSubstr("case.units: expected \"m\" or \"mm\""));
  EXPECT_THAT(error_of("[case]\nname = \"x\"\n"), HasSubstr("no geometry"));
  EXPECT_THAT(error_of(with("[[0, 0], [10, 0]", "[[-1, 0], [10, 0]")), HasSubstr("is open"));
  EXPECT_THAT(error_of(with("[[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]]",
                            "[[-1, 0], [10, 0], [10, 10], [-1, 10], [-1, 0]]")),
              HasSubstr("negative r"));
  EXPECT_THAT(error_of(with("name = \"gap\"", "name = \"core\"")), HasSubstr("used twice"));
  EXPECT_THAT(error_of(with("name = \"gap\"", "name = \"air\"")), HasSubstr("reserved"));
  EXPECT_THAT(error_of(with("gap = \"radial\"", "gap = \"axial\"")),
              HasSubstr("expected \"annular\" or \"radial\""));
  EXPECT_THAT(error_of(valid + "[geometry]\ntemplate = \"annular_valve\"\n"),
              HasSubstr("not both"));
  EXPECT_THAT(error_of("x = [1,\n"), HasSubstr("bad.toml:"));
  EXPECT_THAT(error_of("x = [1,\n"), HasSubstr("TOML syntax error"));
}

TEST(CaseErrors, UnreadableFile) {
  try {
    read_case_file("/nonexistent/case.toml");
    FAIL() << "no error";
  } catch (const rheomag::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("/nonexistent/case.toml: cannot open file"));
  }
  try {
    load_case("case.stl");
    FAIL() << "no error";
  } catch (const rheomag::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("expected a .toml case or a FEMM .fem file"));
  }
}

// Sections of later links pass through and stay readable from Case::table.
TEST(CaseErrors, LaterLinkSectionsPassThrough) {
  // In the program the fluid layer registers [fluid]; this test links only the case layer.
  register_case_section("fluid");
  const Case c = parse_case(valid + "[fluid]\nmodel = \"bingham\"\n", "ok.toml");
  EXPECT_EQ(c.table["fluid"]["model"].value_or(std::string()), "bingham");
}
