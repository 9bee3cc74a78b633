// FEMM .fem import: the hand-written tests/data/pot_core.fem (FEMM 4.2 text format, Windows line
// endings) read field by field, and every malformed or unsupported input -> InputError with
// file:line. (The solved comparison with the equivalent TOML case is in test_femm_equivalence.)

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "case/case_file.hpp"
#include "case/femm_import.hpp"
#include "core/error.hpp"

using namespace rheomag::cases;
using ::testing::HasSubstr;

namespace {

std::string pot_core_text() {
  std::ifstream in(std::string(RHEOMAG_TEST_DATA) + "/pot_core.fem", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string error_of(const std::string& text) {
  try {
    parse_femm(text, "bad.fem");
  } catch (const rheomag::InputError& e) {
    return e.what();
  }
  return "no error";
}

/// pot_core.fem with the first occurrence of `from` replaced by `to`.
std::string with(const std::string& from, const std::string& to) {
  std::string text = pot_core_text();
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST(FemmImport, PotCoreFieldByField) {
  const Problem p = read_femm_file(std::string(RHEOMAG_TEST_DATA) + "/pot_core.fem");
  EXPECT_EQ(p.symmetry, Symmetry::axisymmetric);
  EXPECT_EQ(p.outer, OuterBoundary::none);
  // 14 points in millimetres; the 180-degree arc at 1.875 degrees per side adds 95 points
  // and 96 segments to the 17 straight ones.
  ASSERT_EQ(p.geometry.points.size(), 14u + 95u);
  EXPECT_EQ(p.geometry.segments.size(), 17u + 96u);
  EXPECT_DOUBLE_EQ(p.geometry.points[2].r, 30e-3);
  EXPECT_DOUBLE_EQ(p.geometry.points[13].z, 152.5e-3);
  // The arc's points lie on the circle of radius 150 mm about (0, 2.5 mm).
  for (std::size_t i = 14; i < p.geometry.points.size(); ++i)
    EXPECT_NEAR(std::hypot(p.geometry.points[i].r, p.geometry.points[i].z - 2.5e-3), 0.15, 1e-12);
  // Boundary A = 0 on the arc segments only.
  ASSERT_EQ(p.boundaries.size(), 1u);
  EXPECT_EQ(p.boundaries[0].kind, BoundaryKind::prescribed_a);
  int marked = 0;
  for (const auto& s : p.geometry.segments) marked += s.boundary == 0;
  EXPECT_EQ(marked, 96);
  // Block labels -> regions with materials, circuit, turns and mesh sizes.
  ASSERT_EQ(p.geometry.regions.size(), 5u);
  EXPECT_EQ(p.geometry.regions[0].name, "AISI 1010_1");
  EXPECT_EQ(p.geometry.regions[1].name, "Copper");
  EXPECT_EQ(p.geometry.regions[4].name, "Air_2");
  const Material& iron = p.materials[p.regions[0].material];
  EXPECT_EQ(iron.bh.size(), 38u);  // the 38 points of the AISI 1010 curve, (0, 0) included
  EXPECT_DOUBLE_EQ(iron.conductivity.value_or(0.0), 5.8e6);
  EXPECT_EQ(p.regions[1].turns, 200.0);
  EXPECT_EQ(p.regions[1].circuit, 0);
  ASSERT_EQ(p.circuits.size(), 1u);
  EXPECT_EQ(p.circuits[0].name, "coil");
  EXPECT_EQ(p.circuits[0].current, 10.0);
  // FEMM mesh size d -> edge d sqrt(pi / sqrt 3): the file's d = 0.74252 mm gives 1 mm.
  EXPECT_NEAR(p.geometry.regions[0].mesh_size, 1e-3, 1e-9);
  EXPECT_EQ(p.geometry.regions[4].mesh_size, 0.0);  // -1 = automatic
}

TEST(FemmImport, LengthUnitsAndLineEndings) {
  // Unix line endings and inches give the same geometry scaled by 25.4.
  std::string unix_text = pot_core_text();
  unix_text.erase(std::remove(unix_text.begin(), unix_text.end(), '\r'), unix_text.end());
  const std::size_t at = unix_text.find("millimeters");
  const Problem inches = parse_femm(unix_text.replace(at, 11, "inches"), "inches.fem");
  EXPECT_DOUBLE_EQ(inches.geometry.points[2].r, 30 * 0.0254);
  for (const auto& [unit, metres] : {std::pair{"centimeters", 1e-2},
                                     {"meters", 1.0},
                                     {"mils", 2.54e-5},
                                     {"micrometers", 1e-6}}) {
    const Problem p = parse_femm(with("millimeters", unit), "units.fem");
    EXPECT_DOUBLE_EQ(p.geometry.points[2].r, 30 * metres) << unit;
  }
  EXPECT_THAT(error_of(with("millimeters", "furlongs")),
              HasSubstr("bad.fem:7: [LengthUnits]: expected inches, millimeters"));
}

TEST(FemmImport, PlanarProblemNeedsAPrescribedBoundary) {
  const Problem planar = parse_femm(with("axisymmetric", "planar"), "planar.fem");
  EXPECT_EQ(planar.symmetry, Symmetry::planar);
  EXPECT_DOUBLE_EQ(planar.depth, 1e-3);  // [Depth] = 1 in millimetres
  // Without the A = 0 arc (boundary marker 0) a planar model has no unique solution.
  // Axisymmetric: A = 0 on the axis suffices (as in FEMM), no boundary needed.
  EXPECT_EQ(error_of(with("0\t13\t180\t1.875\t1", "0\t13\t180\t1.875\t0")), "no error");
  std::string text = with("axisymmetric", "planar");
  text.replace(text.find("0\t13\t180\t1.875\t1"), 17, "0\t13\t180\t1.875\t0");
  EXPECT_THAT(error_of(text), HasSubstr("planar model without any prescribed-A boundary"));
}

TEST(FemmImport, MixedBoundaryIsImported) {
  const Problem p = parse_femm(with("<BdryType> = 0", "<BdryType> = 2"), "mixed.fem");
  EXPECT_EQ(p.boundaries[0].kind, BoundaryKind::mixed);
}

TEST(FemmImport, UnsupportedFeaturesAreRejectedClearly) {
  EXPECT_THAT(error_of(with("[Frequency]   =  0", "[Frequency]   =  50")),
              HasSubstr("bad.fem:2: [Frequency] is not 0: time-harmonic problems"));
  EXPECT_THAT(error_of(with("<BdryType> = 0", "<BdryType> = 1")), HasSubstr("small skin depth"));
  EXPECT_THAT(error_of(with("<BdryType> = 0", "<BdryType> = 3")),
              HasSubstr("strategic dual image"));
  EXPECT_THAT(error_of(with("<BdryType> = 0", "<BdryType> = 4")),
              HasSubstr("periodic/antiperiodic boundaries (BdryType 4) are not supported"));
  EXPECT_THAT(error_of(with("<BdryType> = 0", "<BdryType> = 5")), HasSubstr("BdryType 5"));
  EXPECT_THAT(error_of(with("<A_1> = 0", "<A_1> = 0.5")), HasSubstr("A_1, A_2 not 0"));
  // H_c of the iron block (the second block) -> permanent magnet.
  std::string magnet = pot_core_text();
  const std::size_t iron = magnet.find("<BlockName> = \"AISI 1010\"");
  magnet.replace(magnet.find("<H_c> = 0", iron), 9, "<H_c> = 9e5");
  EXPECT_THAT(error_of(magnet), HasSubstr("block 'AISI 1010': permanent magnets (H_c not 0)"));
  EXPECT_THAT(error_of(with("<J_re> = 0", "<J_re> = 2")), HasSubstr("source current density J"));
  EXPECT_THAT(error_of(with("<CircuitType> = 1", "<CircuitType> = 0")),
              HasSubstr("parallel circuit 'coil' (CircuitType 0) with 200 turns"));
  EXPECT_THAT(error_of(with("<Mu_x> = 1\r\n    <Mu_y> = 1", "<Mu_x> = 1\r\n    <Mu_y> = 2")),
              HasSubstr("anisotropic"));
  EXPECT_THAT(error_of(with("60\t0\t1\t-1\t0\t0\t0\t1\t0", "60\t0\t1\t-1\t0\t0\t0\t1\t1")),
              HasSubstr("external region (Kelvin transformation)"));
}

TEST(FemmImport, MalformedOrTruncatedFiles) {
  const std::string text = pot_core_text();
  // Truncated inside the point list: names the line where the file ends and what was expected.
  const std::string truncated = text.substr(0, text.find("[NumSegments]"));
  EXPECT_THAT(error_of(truncated.substr(0, truncated.rfind("0\t152.5"))),
              HasSubstr("file ends early: expected point 14 of 14 after [NumPoints]"));
  EXPECT_THAT(error_of(text.substr(0, text.find("<EndCircuit>"))),
              HasSubstr("file ends early: expected <endcircuit>"));
  EXPECT_THAT(error_of(with("30\t-20\t0\t0", "30\tabc\t0\t0")),
              HasSubstr("expected a number for point, got 'abc'"));
  EXPECT_THAT(error_of(with("30\t-20\t0\t0", "30\tnan\t0\t0")),
              HasSubstr("expected a finite number for point, got 'nan'"));
  EXPECT_THAT(error_of(with("0\t1\t-1\t0\t0\t0", "0\t99\t-1\t0\t0\t0")),
              HasSubstr("point number 99 does not exist"));
  EXPECT_THAT(error_of(with("[BlockProps]  =  3", "[BlockProps]  =  4")),
              HasSubstr("[blockprops] declares 4 properties but the file has 3"));
  EXPECT_THAT(error_of(with("[Depth]", "[Deepth]")), HasSubstr("unknown .fem key [deepth]"));
  EXPECT_THAT(error_of(with("[Frequency]   =  0\r\n", "")), HasSubstr("no [Frequency] key"));
  EXPECT_THAT(error_of("garbage\n"), HasSubstr("bad.fem:1: expected a [Key] = value line"));
  EXPECT_THAT(error_of(""), HasSubstr("no [Frequency] key"));
  EXPECT_THAT(error_of(with("5\t0\t2\t", "5\t0\t7\t")), HasSubstr("block type 7 does not exist"));
  EXPECT_THAT(
      error_of(with("17\t0\t3\t0.7425152493\t1\t0\t0\t200", "17\t0\t3\t0.7425152493\t1\t0\t0\t0")),
      HasSubstr("has 0 turns"));
  EXPECT_THAT(error_of(with("0\t13\t180\t1.875", "0\t13\t200\t1.875")),
              HasSubstr("arc angle must be in (0, 180]"));
}

TEST(FemmImport, BhTablesAreChecked) {
  // Swap two B values of the iron curve: not monotone.
  EXPECT_THAT(error_of(with("0.265665\t100.1821", "0.1\t100.1821")),
              HasSubstr("block 'AISI 1010': B-H table is not monotone at point 3"));
  // A one-point table.
  std::string one = pot_core_text();
  const std::size_t start = one.find("<BHPoints> = 38");
  const std::size_t end = one.find("  <EndBlock>", start);
  one.replace(start, end - start, "<BHPoints> = 1\r\n0.5\t100\r\n");
  EXPECT_THAT(error_of(one), HasSubstr("a B-H table needs at least 2 points"));
}

TEST(FemmImport, HolesAndNoMeshBlocks) {
  // Block type 0 (<No Mesh>) marks a hole.
  const Problem p = parse_femm(with("15\t22.5\t2\t", "15\t22.5\t0\t"), "hole.fem");
  EXPECT_TRUE(p.geometry.regions[3].hole);
  EXPECT_EQ(p.geometry.regions[3].name, "no_mesh");
}

TEST(FemmImport, LoadCaseDispatchesOnExtension) {
  const Case c = load_case(std::string(RHEOMAG_TEST_DATA) + "/pot_core.fem");
  EXPECT_EQ(c.name, "pot_core");
  EXPECT_EQ(c.problem.outer, OuterBoundary::none);
  EXPECT_TRUE(c.table.empty());
}
