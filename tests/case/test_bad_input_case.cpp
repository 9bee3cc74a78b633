// Bad input of case files found by issue #18's probe: each physical quantity is read in its
// declared domain (whole turns, an MR fluid where a fluid belongs, a bounded outer radius), and
// the refusal names file, line and key.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "case/case_file.hpp"
#include "core/error.hpp"

using namespace rheomag::cases;

namespace {

/// The bundled annular valve case (template form, units mm).
std::string annular_valve() {
  std::ifstream in(std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml");
  std::ostringstream text;
  text << in.rdbuf();
  // Only the case layer is linked here: drop the [valve] table of the valve link.
  return text.str().substr(0, text.str().find("\n[valve]"));
}

/// The 1-based line of the first occurrence of `what` in `text`.
int line_of(const std::string& text, const std::string& what) {
  const std::size_t at = text.find(what);
  EXPECT_NE(at, std::string::npos) << what;
  int line = 1;
  for (std::size_t i = 0; i < at; ++i) line += text[i] == '\n';
  return line;
}

/// `text` with the first occurrence of `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

/// The InputError message of parsing `text`, or "no error".
std::string error_of(const std::string& text) {
  try {
    parse_case(text, "valve.toml");
  } catch (const rheomag::InputError& e) {
    return e.what();
  }
  return "no error";
}

/// A general case of one square winding region with `turns` (TOML text) turns.
std::string winding_case(const std::string& turns) {
  return "[[circuit]]\nname = \"coil\"\n[[region]]\nname = \"winding\"\nmaterial = \"Copper\"\n"
         "coil = { circuit = \"coil\", turns = " +
         turns + " }\npoints = [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]]\n";
}

}  // namespace

TEST(BadInputCase, BundledCaseReads) {
  EXPECT_EQ(error_of(annular_valve()), "no error");
}

// turns = 600.5 was used as 600.5 turns while the summary printed 600.
TEST(BadInputCase, TemplateTurnsAreWhole) {
  const std::string text = replaced(annular_valve(), "turns = 600 ", "turns = 600.5 ");
  EXPECT_EQ(error_of(text),
            "valve.toml:" + std::to_string(line_of(text, "turns = 600.5")) +
                ": geometry.turns: expected a whole number in [1, 1000000000], got 600.5");
}

TEST(BadInputCase, RegionCoilTurnsAreWhole) {
  const std::string text = winding_case("10.5");
  EXPECT_NE(error_of(text).find(
                "region[1].coil.turns: expected a whole number in [1, 1000000000], got 10.5"),
            std::string::npos)
      << error_of(text);
}

// 1e15 turns were solved (lambda 1.7e26 Wb) and `export` wrote 9223372036854775807 turns as
// -9223372036854775808 (a double->long overflow); a wire of 10 nm wound the same count from the
// fill factor. Turns are bounded by 10^9, FEMM's integer column.
TEST(BadInputCase, TurnsAreBounded) {
  const std::string text = replaced(annular_valve(), "turns = 600 ", "turns = 1e15 ");
  EXPECT_EQ(error_of(text), "valve.toml:" + std::to_string(line_of(text, "turns = 1e15")) +
                                ": geometry.turns: expected a whole number in [1, 1000000000], "
                                "got 1e+15");
  const std::string region = winding_case("9223372036854775807");
  EXPECT_NE(error_of(region).find("region[1].coil.turns: expected a whole number in [1, "
                                  "1000000000], got 9.22337203685e+18"),
            std::string::npos)
      << error_of(region);
  const std::string wound =
      replaced(annular_valve(), "turns = 600 ", "wire = \"0.00001 mm\"\nfill_factor = 0.5 ");
  EXPECT_NE(error_of(wound).find("geometry.fill_factor: coil: 0.000010 mm wire at fill factor "
                                 "0.500000 gives more than 10^9 turns"),
            std::string::npos)
      << error_of(wound);
}

// One coordinate far from the rest (1e300, or 1e9 mm typed for 1e-9) makes the domain-relative
// merge tolerance huge, and a region elsewhere was refused with "repeated point (0, -20) mm" and
// no hint why; the message now gives the tolerance and what sets it.
TEST(BadInputCase, FarCoordinateNamesTheMergeTolerance) {
  const std::string text = R"([case]
units = "mm"
[[region]]
name = "pot"
material = "Air"
points = [[0, -20], [30, -20], [30, 18], [0, 18], [0, -20]]
[[region]]
name = "lid"
material = "Air"
points = [[0, 20], [30, 20], [30, 1e300], [0, 20]]
)";
  EXPECT_NE(error_of(text).find("region 'pot': repeated point (0, -20) mm (point 1): the next "
                                "point lies within 1e+288 m, the merge tolerance (1e-9 of the "
                                "largest coordinate of the case;"),
            std::string::npos)
      << error_of(text);
}

// A steel fluid_material got the MR-fluid pressure drop of [case] fluid.
TEST(BadInputCase, FluidMaterialMustBeAnMrFluid) {
  const std::string text =
      replaced(annular_valve(), "fluid_material = \"MRC-C1L\"", "fluid_material = \"AISI 1010\"");
  const std::string message = error_of(text);
  EXPECT_EQ(message.rfind("valve.toml:" + std::to_string(line_of(text, "fluid_material =")) +
                              ": geometry.fluid_material: 'AISI 1010' is not an MR fluid (its "
                              "material has no [rheology] table); expected one of: ",
                          0),
            0u)
      << message;
  EXPECT_NE(message.find("MRC-C1L"), std::string::npos) << message;
}

TEST(BadInputCase, CaseFluidMustBeAnMrFluid) {
  const std::string text = replaced(annular_valve(), "fluid = \"MRC-C1L\"", "fluid = \"Copper\"");
  EXPECT_EQ(error_of(text).rfind("valve.toml:" + std::to_string(line_of(text, "fluid = \"Copper")) +
                                     ": case.fluid: 'Copper' is not an MR fluid",
                                 0),
            0u)
      << error_of(text);
}

TEST(BadInputCase, GapsHoldTheCaseFluid) {
  const std::string text =
      replaced(annular_valve(), "fluid_material = \"MRC-C1L\"", "fluid_material = \"MRF-132DG\"");
  EXPECT_NE(error_of(text).find("holds 'MRF-132DG'; expected the case's MR fluid 'MRC-C1L'"),
            std::string::npos)
      << error_of(text);
}

// A huge outer_radius_factor gave "points 0 and 7 coincide" without naming the key.
TEST(BadInputCase, OuterRadiusFactorBounded) {
  const std::string text =
      replaced(annular_valve(), "outer_radius_factor = 5.0", "outer_radius_factor = 1.0e9");
  EXPECT_EQ(error_of(text),
            "valve.toml:" + std::to_string(line_of(text, "outer_radius_factor = 1.0e9")) +
                ": solver.outer_radius_factor: expected a number in (1, 100], got 1000000000");
}
