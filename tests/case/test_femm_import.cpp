// FEMM .fem import: the hand-written tests/data/pot_core.fem (FEMM 4.2 text format, Windows line
// endings) read field by field, and every malformed or unsupported input -> InputError with
// file:line. (The solved comparison with the equivalent TOML case is in test_femm_equivalence.)

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "case/case_file.hpp"
#include "case/femm_import.hpp"
#include "core/error.hpp"
#include "tests/case/pot_core_magnet.hpp"

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
  // Interpolated as FEMM does (its natural cubic spline), not with rheomag's monotone cubic.
  EXPECT_EQ(iron.bh_interpolation, BhInterpolation::femm_natural_spline);
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

// "block label column 8 must be an integer" for 1e12 turns did not say which field or what was
// read.
TEST(FemmImport, BlockLabelIntegerColumnsNamed) {
  EXPECT_THAT(error_of(with("17\t0\t3\t0.7425152493\t1\t0\t0\t200",
                            "17\t0\t3\t0.7425152493\t1\t0\t0\t1e12")),
              HasSubstr("bad.fem:171: block label column 8 (turns): expected a whole number "
                        "within +-1e9, got 1e+12"));
  EXPECT_THAT(error_of(with("17\t0\t3\t0.7425152493\t1", "17\t0\t3.5\t0.7425152493\t1")),
              HasSubstr("bad.fem:171: block label column 3 (block type): expected a whole number "
                        "within +-1e9, got 3.5"));
}

// A negative Sigma was kept as the block's conductivity (eddy currents that grow in a transient
// run); a negative count said only "bad count".
TEST(FemmImport, NegativeConductivityAndCountNamed) {
  EXPECT_THAT(error_of(with("<Sigma> = 58", "<Sigma> = -58")),
              HasSubstr("block 'Copper': Sigma = -58 MS/m; expected a conductivity >= 0"));
  EXPECT_THAT(error_of(with("<BHPoints> = 38", "<BHPoints> = -1")),
              HasSubstr("bad.fem:67: [BHPoints]: expected a count in [0, 10000000], got -1"));
}

// A .fem saved by a Windows editor starts with a UTF-8 byte-order mark; it was refused as
// "bad.fem:1: expected a [Key] = value line, got '\xEF\xBB\xBF[Format] = 4.0'".
TEST(FemmImport, ByteOrderMarkIsSkipped) {
  const Problem plain = parse_femm(pot_core_text(), "plain.fem");
  for (const std::string& text :
       {"\xEF\xBB\xBF" + pot_core_text(), "\xEF\xBB\xBF" + with("\n", "\r\n")}) {
    const Problem marked = parse_femm(text, "bom.fem");
    ASSERT_EQ(marked.geometry.points.size(), plain.geometry.points.size());
    EXPECT_DOUBLE_EQ(marked.geometry.points[2].r, plain.geometry.points[2].r);
    EXPECT_EQ(marked.regions.size(), plain.regions.size());
  }
}

TEST(FemmImport, DepthIsIgnoredInAxisymmetricModels) {
  // FEMM's Lua idiom mi_probdef(0, "millimeters", "axi", 1e-8, 0, 30) writes [Depth] = 0; FEMM
  // ignores the depth of an axisymmetric problem, and so does the reader.
  for (const char* depth : {"0", "-3"}) {
    const Problem p =
        parse_femm(with("[Depth]       =  1", std::string("[Depth] = ") + depth), "axi.fem");
    EXPECT_EQ(p.symmetry, Symmetry::axisymmetric);
    EXPECT_EQ(p.geometry.points.size(), 14u + 95u);
  }
  // A planar problem needs a positive depth: the message names the [Depth] line.
  std::string planar = with("axisymmetric", "planar");
  planar.replace(planar.find("[Depth]       =  1"), 18, "[Depth] = 0");
  EXPECT_THAT(error_of(planar), HasSubstr("bad.fem:6: [Depth] must be positive in a planar"));
}

TEST(FemmImport, PlanarProblemWithoutPrescribedBoundaryIsAccepted) {
  const Problem planar = parse_femm(with("axisymmetric", "planar"), "planar.fem");
  EXPECT_EQ(planar.symmetry, Symmetry::planar);
  EXPECT_DOUBLE_EQ(planar.depth, 1e-3);  // [Depth] = 1 in millimetres
  // Without the A = 0 arc the model is read; the solver fixes the gauge (test_femm_models).
  std::string text = with("axisymmetric", "planar");
  text.replace(text.find("0\t13\t180\t1.875\t1"), 17, "0\t13\t180\t1.875\t0");
  EXPECT_EQ(error_of(text), "no error");
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
  // A (anti)periodic property on three edges cannot be paired (test_femm_periodic.cpp solves
  // pairs; a property on one edge is dropped, as FEMM does: FemmImport.UnpairedPeriodicEdge...).
  std::string three = with("<BdryType> = 0", "<BdryType> = 4");
  for (const std::string segment : {"\n11\t10\t-1\t0", "\n12\t13\t-1\t0"})
    three.replace(three.find(segment), segment.size(), segment.substr(0, segment.size() - 1) + "1");
  EXPECT_THAT(error_of(three),
              HasSubstr("periodic boundary 'A=0' (BdryType 4, defined at line 16) is used by 3 "
                        "edge(s) (lines 164, 165, 167)"));
  EXPECT_THAT(error_of(with("<BdryType> = 0", "<BdryType> = 6")),
              HasSubstr("periodic air-gap elements (BdryType 6)"));
  EXPECT_THAT(error_of(with("<BdryType> = 0", "<BdryType> = 7")),
              HasSubstr("antiperiodic air-gap elements (BdryType 7)"));
  // A_1, A_2 are solved (FemmUniformField.*), but not with the angle of polar coordinates.
  std::string polar = with("<A_1> = 0", "<A_1> = 0.5");
  polar.replace(polar.find("cartesian"), 9, "polar");
  EXPECT_THAT(error_of(polar),
              HasSubstr("A_0 + A_1 r + A_2 theta in polar coordinates ([Coordinates] = polar, "
                        "line 9)"));
  EXPECT_EQ(error_of(with("<A_1> = 0", "<A_1> = 0.5")), "no error");
  EXPECT_THAT(error_of(with("<H_cAngle> = 0", "<H_cAngle> = 10")), HasSubstr("H_cAngle = 10"));
  // Laminations along x at fill < 1 make a B-H block nonlinear and anisotropic: refused (a linear
  // block is solved, FemmAnisotropic.*).
  std::string across = pot_core_text();
  const std::size_t steel = across.find("<BlockName> = \"AISI 1010\"");
  across.replace(across.find("<LamType> = 0", steel), 13, "<LamType> = 1");
  across.replace(across.find("<LamFill> = 1", steel), 13, "<LamFill> = 0.9");
  EXPECT_THAT(error_of(across), HasSubstr("with LamFill < 1 is a nonlinear anisotropic material, "
                                          "which is not supported; a linear one"));
  EXPECT_THAT(error_of(with("<LamType> = 0", "<LamType> = 9")), HasSubstr("unknown LamType 9"));
  EXPECT_THAT(error_of(with("<LamFill> = 1", "<LamFill> = 0")), HasSubstr("LamFill = 0"));
  // A parallel circuit of a 200-turn label is FEMM's: one current, the turns a winding's mark
  // (FemmCircuits.* solve such circuits against closed forms).
  const Problem parallel = parse_femm(with("<CircuitType> = 1", "<CircuitType> = 0"), "p.fem");
  ASSERT_EQ(parallel.circuits.size(), 1u);
  EXPECT_TRUE(parallel.circuits[0].parallel);
  ASSERT_EQ(parallel.warnings.size(), 1u);
  EXPECT_THAT(parallel.warnings[0],
              HasSubstr("block label with 200 turns in parallel circuit 'coil': FEMM shares"));
  // Mu_x != Mu_y: a linear anisotropic material (solved in FemmAnisotropic.*); Mu_y <= 0 named.
  const Problem skewed =
      parse_femm(with("<Mu_x> = 1\r\n    <Mu_y> = 1", "<Mu_x> = 1\r\n    <Mu_y> = 2"), "s.fem");
  const Material& skewed_air = skewed.materials[skewed.regions[4].material];
  ASSERT_TRUE(skewed_air.mu_r_axes.has_value());
  EXPECT_EQ(*skewed_air.mu_r_axes, (std::array<double, 2>{1.0, 2.0}));
  EXPECT_THAT(error_of(with("<Mu_x> = 1\r\n    <Mu_y> = 1", "<Mu_x> = 1\r\n    <Mu_y> = 0")),
              HasSubstr("Mu_y = 0; expected a finite relative permeability > 0"));
  // An axisymmetric external region needs the header's radii (FemmModels.AxisymmetricKelvin...).
  EXPECT_THAT(error_of(with("60\t0\t1\t-1\t0\t0\t0\t1\t0", "60\t0\t1\t-1\t0\t0\t0\t1\t1")),
              HasSubstr("needs [extRo] > 0 and [extRi] > 0"));
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

// FEMM's mesher drops an (anti)periodic property that only one edge carries (xfemm 35baec4,
// fmesher/writepoly.cpp); the edge then has no condition, and the user is told.
TEST(FemmImport, UnpairedPeriodicEdgeHasNoConditionAsInFemm) {
  for (const char* type : {"<BdryType> = 4", "<BdryType> = 5"}) {
    const Problem p = parse_femm(with("<BdryType> = 0", type), "one.fem");
    for (const auto& segment : p.geometry.segments) EXPECT_EQ(segment.boundary, -1) << type;
    ASSERT_EQ(p.warnings.size(), 1u) << type;
    EXPECT_THAT(p.warnings[0], HasSubstr("one.fem:167: "));
    EXPECT_THAT(p.warnings[0], HasSubstr("is used by this edge only; it pairs nothing, so the "
                                         "edge gets no condition, as in FEMM"));
  }
}

// A magnet with a B-H table (FEMM's curve shifted by H_c): the table and H_c both kept
// (FemmModels.NonlinearMagnetIsExact solves one).
TEST(FemmImport, NonlinearMagnetKeepsItsCurveAndCoercivity) {
  std::string magnet = pot_core_text();
  const std::size_t iron = magnet.find("<BlockName> = \"AISI 1010\"");
  magnet.replace(magnet.find("<H_c> = 0", iron), 9, "<H_c> = 9e5");
  const Problem p = parse_femm(magnet, "magnet.fem");
  const auto found = std::find_if(p.materials.begin(), p.materials.end(),
                                  [](const Material& m) { return m.name == "AISI 1010"; });
  ASSERT_NE(found, p.materials.end());
  EXPECT_EQ(found->coercivity, 9e5);
  EXPECT_EQ(found->bh.size(), 38u);
  EXPECT_TRUE(p.warnings.empty());
}

TEST(FemmImport, BhTablesAreChecked) {
  // Swap two H values of the iron curve: smoothed as FEMM does (one pass here), with a warning
  // naming the block and the point, and the table rises.
  std::string swapped = pot_core_text();
  swapped.replace(swapped.find("1.51721\t1587.7793"), 17, "1.51721\t1998.8957");
  swapped.replace(swapped.find("1.54452\t1998.8957"), 17, "1.54452\t1587.7793");
  const Problem p = parse_femm(swapped, "swapped.fem");
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_THAT(p.warnings[0],
              HasSubstr("swapped.fem:50: block 'AISI 1010': the B-H table does not increase at "
                        "point 16 [1.54452, 1587.7793]; smoothed as FEMM does: every interior "
                        "point averaged with its two neighbours, 1 pass"));
  const auto iron = std::find_if(p.materials.begin(), p.materials.end(),
                                 [](const Material& m) { return m.name == "AISI 1010"; });
  ASSERT_NE(iron, p.materials.end());
  const auto& bh = iron->bh;
  ASSERT_EQ(bh.size(), 38u);
  for (std::size_t i = 1; i < bh.size(); ++i) {
    EXPECT_GT(bh[i].b, bh[i - 1].b) << i;
    EXPECT_GT(bh[i].h, bh[i - 1].h) << i;
  }
  // The smoothed curve is FEMM's: the mean of each point and its neighbours (point 2).
  EXPECT_NEAR(bh[1].b, (0.0 + 0.211862 + 0.265665) / 3.0, 1e-15);
  // A table no rising curve can follow (its last B back at 0) is refused.
  std::string back = pot_core_text();
  back.replace(back.find("2.47124\t316803.62"), 17, "0.0\t316803.62");
  EXPECT_THAT(error_of(back), HasSubstr("block 'AISI 1010': B-H table is not monotone"));
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

TEST(FemmImport, MaterialFieldsAsFemmUsesThem) {
  // Air block (the first): J in MA/m^2 -> A/m^2 on its regions.
  const Problem j = parse_femm(with("<J_re> = 0", "<J_re> = 2"), "j.fem");
  const Material& air = j.materials[j.regions[4].material];
  EXPECT_EQ(air.name, "Air");
  EXPECT_DOUBLE_EQ(j.regions[4].current_density, 2e6);
  // In-plane laminations (LamType 0) with fill f: linear mu' = f mu + 1 - f; a B-H curve
  // becomes B' = f B + (1 - f) mu0 H at the table's H.
  std::string lam = pot_core_text();
  const std::size_t iron = lam.find("<BlockName> = \"AISI 1010\"");
  lam.replace(lam.find("<LamFill> = 1", iron), 13, "<LamFill> = 0.5");
  const Problem full = parse_femm(pot_core_text(), "full.fem");
  const Problem half = parse_femm(lam, "lam.fem");
  const Material& iron_full = full.materials[full.regions[0].material];
  const Material& iron_half = half.materials[half.regions[0].material];
  ASSERT_EQ(iron_full.bh.size(), iron_half.bh.size());
  for (std::size_t k = 0; k < iron_full.bh.size(); ++k) {
    EXPECT_DOUBLE_EQ(iron_half.bh[k].h, iron_full.bh[k].h);
    EXPECT_NEAR(iron_half.bh[k].b,
                0.5 * iron_full.bh[k].b + 0.5 * 4e-7 * std::numbers::pi * iron_full.bh[k].h, 1e-12);
  }
  std::string air_lam = with("<LamFill> = 1", "<LamFill> = 0.25");
  air_lam.replace(air_lam.find("<Mu_x> = 1"), 10, "<Mu_x> = 1001");
  air_lam.replace(air_lam.find("<Mu_y> = 1"), 10, "<Mu_y> = 1001");
  const Problem linear = parse_femm(air_lam, "linear.fem");
  EXPECT_DOUBLE_EQ(linear.materials[linear.regions[4].material].mu_r, 0.25 * 1001 + 0.75);
  // Wire blocks (LamType >= 3): FEMM's magnetostatic solver uses mu_r = 1.
  const Problem wire = parse_femm(with("<LamType> = 0", "<LamType> = 3"), "wire.fem");
  EXPECT_DOUBLE_EQ(wire.materials[wire.regions[4].material].mu_r, 1.0);
  // Conductivity (MS/m -> S/m) is kept for transient work.
  EXPECT_DOUBLE_EQ(full.materials[full.regions[0].material].conductivity.value_or(0.0), 5.8e6);
}

TEST(FemmImport, MagnetsAndPointProperties) {
  // A linear magnet block with a direction expression on its label; a point current.
  const std::string text = rheomag::testing::pot_core_with_magnet(pot_core_text(), "theta + 90");
  const Problem p = parse_femm(text, "magnet.fem");
  const Material& magnet = p.materials[p.regions[4].material];
  EXPECT_DOUBLE_EQ(magnet.coercivity, 8e5);
  EXPECT_EQ(p.regions[4].magnetisation.expression, "theta + 90");
  EXPECT_DOUBLE_EQ(p.regions[4].magnetisation.length_unit, 1e-3);
  ASSERT_EQ(p.point_conditions.size(), 1u);
  EXPECT_FALSE(p.point_conditions[0].prescribed);
  EXPECT_DOUBLE_EQ(p.point_conditions[0].current, 3.0);
  EXPECT_DOUBLE_EQ(p.geometry.points[p.point_conditions[0].point].r, 30e-3);
  // A direction expression that does not parse names the label's line.
  std::string bad = text;
  bad.replace(bad.find("theta + 90"), 10, "theta +* 90");
  EXPECT_THAT(error_of(bad), HasSubstr("magnetisation direction expression 'theta +* 90'"));
  std::string unknown = text;
  unknown.replace(unknown.find("theta + 90"), 10, "phi");
  EXPECT_THAT(error_of(unknown), HasSubstr("'phi'"));
  // A point property number that does not exist.
  std::string missing = text;
  missing.replace(missing.find("30\t-20\t1\t0"), 10, "30\t-20\t4\t0");
  EXPECT_THAT(error_of(missing), HasSubstr("point property number 4 does not exist"));
}
