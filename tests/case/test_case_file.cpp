// Case-file reader: reference cases, templates, general regions with arcs, PSLG invariants.
// Geometric tests are exact up to floating-point rounding (tolerances 1e-12 relative) except
// the arc area, which follows the chord discretisation error formula stated below.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "case/geometry_check.hpp"
#include "case/templates.hpp"

// The bundled cases carry sections of later layers ([valve], [optimise]); in the program those
// layers register them, and this test, which links only the layers below, registers them itself.
const bool kLaterSectionsRegistered = rheomag::cases::register_case_section("valve") &&
                                      rheomag::cases::register_case_section("optimise");

using namespace rheomag::cases;
using rheomag::mesh::GapKind;
using rheomag::mesh::Point;

namespace {

Case reference(const std::string& name) {
  return read_case_file(std::string(RHEOMAG_SOURCE_DIR) + "/cases/" + name + ".toml");
}

int region_index(const Case& c, const std::string& name) {
  for (std::size_t i = 0; i < c.problem.geometry.regions.size(); ++i)
    if (c.problem.geometry.regions[i].name == name) return static_cast<int>(i);
  return -1;
}

/// Every segment joins two distinct existing points, no segment appears twice, and no PSLG
/// point lies strictly inside a segment (T-junctions were split).
void expect_clean_pslg(const rheomag::mesh::Pslg& pslg) {
  std::set<std::pair<int, int>> seen;
  const int n = static_cast<int>(pslg.points.size());
  for (const auto& s : pslg.segments) {
    ASSERT_TRUE(s.a >= 0 && s.a < n && s.b >= 0 && s.b < n && s.a != s.b);
    EXPECT_TRUE(seen.insert({std::min(s.a, s.b), std::max(s.a, s.b)}).second);
    const Point a = pslg.points[s.a], b = pslg.points[s.b];
    for (int k = 0; k < n; ++k) {
      if (k == s.a || k == s.b) continue;
      const Point p = pslg.points[k];
      const double len = std::hypot(b.r - a.r, b.z - a.z);
      const double t = ((p.r - a.r) * (b.r - a.r) + (p.z - a.z) * (b.z - a.z)) / (len * len);
      const double d = std::abs((b.r - a.r) * (p.z - a.z) - (b.z - a.z) * (p.r - a.r)) / len;
      EXPECT_FALSE(t > 1e-9 && t < 1 - 1e-9 && d < 1e-12) << "point " << k << " inside segment";
    }
  }
}

}  // namespace

TEST(CaseFile, AnnularValveReferenceCase) {
  const Case c = reference("annular_valve");
  EXPECT_EQ(c.name, "annular_valve");
  EXPECT_EQ(c.fluid, "MRC-C1L");
  EXPECT_EQ(c.geometry_template, "annular_valve");
  const Problem& p = c.problem;
  EXPECT_EQ(p.symmetry, Symmetry::axisymmetric);
  EXPECT_EQ(p.order, 2);
  EXPECT_EQ(p.outer, OuterBoundary::open);
  ASSERT_EQ(p.regions.size(), p.geometry.regions.size());
  ASSERT_EQ(p.circuits.size(), 1u);
  EXPECT_EQ(p.circuits[0].current, 1.0);
  // Background air region is the default region and its material is Air.
  ASSERT_GE(p.geometry.default_region, 0);
  EXPECT_EQ(p.geometry.regions[p.geometry.default_region].name, "air");
  EXPECT_EQ(p.materials[p.regions[p.geometry.default_region].material].name, "Air");
  // Gaps: two annular gaps of MRC-C1L, 1 mm wide at mean radius 19.5 mm.
  for (const char* gap : {"gap_top", "gap_bottom"}) {
    const int i = region_index(c, gap);
    ASSERT_GE(i, 0) << gap;
    EXPECT_EQ(p.geometry.regions[i].gap, GapKind::annular);
    EXPECT_EQ(p.materials[p.regions[i].material].name, "MRC-C1L");
    EXPECT_NEAR(p.geometry.regions[i].seed.r, 19.5e-3, 1e-12);
  }
  const int coil = region_index(c, "coil");
  ASSERT_GE(coil, 0);
  EXPECT_EQ(p.regions[coil].turns, 600.0);
  EXPECT_EQ(p.regions[coil].circuit, 0);
  EXPECT_EQ(p.materials[p.regions[region_index(c, "core")].material].name, "AISI 1010");
  EXPECT_FALSE(p.materials[p.regions[region_index(c, "core")].material].bh.empty());
  expect_clean_pslg(p.geometry);
  // The later links can read their own sections from the kept table.
  EXPECT_TRUE(c.table.contains("geometry"));
}

TEST(CaseFile, MeanderingAndRadialReferenceCases) {
  const Case m = reference("meandering_valve");
  EXPECT_EQ(m.fluid, "MRF-132DG");
  int annular = 0, radial = 0;
  for (const auto& r : m.problem.geometry.regions) {
    annular += r.gap == GapKind::annular;
    radial += r.gap == GapKind::radial;
  }
  EXPECT_EQ(annular, 2);
  EXPECT_EQ(radial, 2);
  expect_clean_pslg(m.problem.geometry);
  const Case r = reference("radial_valve");
  EXPECT_EQ(r.problem.geometry.regions[region_index(r, "gap_inner")].gap, GapKind::radial);
  expect_clean_pslg(r.problem.geometry);
}

// Each template tiles its bounding rectangle exactly: the region areas sum to it, so regions
// neither overlap (also checked by the reader) nor leave holes.
TEST(Templates, RegionsTileTheBoundingRectangle) {
  for (const ValveTemplate& t : valve_templates()) {
    TemplateValues v = default_values(t);
    v.where = t.name;
    const std::vector<RegionOutline> regions = t.build(v);
    double area = 0, r0 = 1e9, r1 = -1e9, z0 = 1e9, z1 = -1e9;
    for (const RegionOutline& region : regions) {
      area += std::abs(signed_area(region.outline));
      for (const Point& p : region.outline) {
        r0 = std::min(r0, p.r), r1 = std::max(r1, p.r), z0 = std::min(z0, p.z),
        z1 = std::max(z1, p.z);
      }
    }
    EXPECT_NEAR(area, (r1 - r0) * (z1 - z0), 1e-12 * (r1 - r0) * (z1 - z0)) << t.name;
    EXPECT_EQ(r0, 0.0) << t.name << " touches the axis";
  }
}

TEST(Templates, AnnularValveDimensionsFollowTheKeys) {
  const Case c = parse_case(R"(
[case]
units = "mm"
[geometry]
template = "annular_valve"
gap_radius = 25
gap_width = 2
[[circuit]]
name = "coil"
current = 2
)",
                            "inline.toml");
  const auto& regions = c.problem.geometry.regions;
  EXPECT_NEAR(regions[region_index(c, "gap_top")].seed.r, 25e-3, 1e-12);
  // Default turns are 600 when not given.
  EXPECT_EQ(c.problem.regions[region_index(c, "coil")].turns, 600.0);
}

// A general case: a rectangle of iron with a semicircular (180 degree) arc edge, an adjacent
// coil sharing part of an edge (T-junction), an annular gap. Units mm.
TEST(CaseFile, GeneralRegionsWithArcs) {
  const Case c = parse_case(R"(
[case]
units = "mm"
[geometry]
max_arc_angle = 10
[[region]]
name = "cap"
material = "AISI 1018"
points = [[0, 0], [10, 0, 180], [0, 10], [0, 0]]
mesh_size = 0.5
[[region]]
name = "winding"
material = "Copper"
points = [[0, -4], [5, -4], [5, 0], [0, 0], [0, -4]]
coil = { circuit = "c1", turns = 50, reversed = true }
[[region]]
name = "slot"
material = "MRF-140CG"
gap = "radial"
points = [[5, -4], [10, -4], [10, 0], [5, 0], [5, -4]]
[[circuit]]
name = "c1"
current = 0.5
)",
                            "inline.toml");
  const Problem& p = c.problem;
  EXPECT_EQ(c.fluid, "MRF-140CG");
  ASSERT_EQ(p.geometry.regions.size(), 4u);  // 3 + air
  EXPECT_EQ(p.regions[1].turns, -50.0);
  EXPECT_NEAR(p.geometry.regions[0].mesh_size, 0.5e-3, 1e-15);
  // The 180 degree arc from (10, 0) to (0, 10) with 10-degree pieces adds 17 interior points:
  // 3 + 17 points for the cap, plus (0,-4), (5,-4), (10,-4) and (5, 0) = 24 points.
  EXPECT_EQ(p.geometry.points.size(), 24u);
  expect_clean_pslg(p.geometry);
  // The cap is the triangle plus the half disc over its hypotenuse: the interior of the circle
  // through (0,0), (10,0), (0,10) in the quadrant r > 0, z > 0. Its seed must lie there.
  const Point seed = p.geometry.regions[0].seed;
  EXPECT_LT(std::hypot(seed.r - 5e-3, seed.z - 5e-3), std::sqrt(50.0) * 1e-3);
  EXPECT_GT(seed.r, 0.0);
  EXPECT_GT(seed.z, 0.0);
}

// Arc discretisation: n equal chords of a circle of radius R; polygon area of a half disc of
// radius R in n pieces = n/2 R^2 sin(pi/n) (exact for the inscribed polygon).
TEST(Arcs, SemicircleMatchesInscribedPolygonArea) {
  const double radius = 2.0;
  std::vector<Point> outline{{radius, 0}};
  append_arc(outline, {radius, 0}, {-radius, 0}, 180.0, 7.0);  // ceil(180/7) = 26 pieces
  ASSERT_EQ(outline.size(), 27u);
  for (const Point& q : outline) EXPECT_NEAR(std::hypot(q.r, q.z), radius, 1e-12);
  const double expected = 26.0 / 2.0 * radius * radius * std::sin(std::numbers::pi / 26.0);
  EXPECT_NEAR(signed_area(outline), expected, 1e-12);
  // Clockwise (negative angle) arcs bulge the other way.
  std::vector<Point> cw{{radius, 0}};
  append_arc(cw, {radius, 0}, {-radius, 0}, -180.0, 7.0);
  EXPECT_NEAR(signed_area(cw), -expected, 1e-12);
}

// Planar cases: depth in file units, negative coordinates allowed, solver options read.
TEST(CaseFile, PlanarCaseAndSolverOptions) {
  const Case c = parse_case(R"(
[case]
units = "mm"
symmetry = "planar"
depth = 40
[solver]
order = 1
min_gap_elements = 6
outer_boundary = "dirichlet"
outer_radius_factor = 3
[[region]]
name = "bar"
material = "AISI 1018"
points = [[-10, -5], [10, -5], [10, 5], [-10, 5], [-10, -5]]
)",
                            "planar.toml");
  const Problem& p = c.problem;
  EXPECT_EQ(p.symmetry, Symmetry::planar);
  EXPECT_DOUBLE_EQ(p.depth, 0.04);
  EXPECT_EQ(p.order, 1);
  EXPECT_EQ(p.min_gap_elements, 6);
  EXPECT_EQ(p.outer, OuterBoundary::dirichlet);
  EXPECT_EQ(p.outer_radius_factor, 3.0);
  EXPECT_NEAR(p.geometry.regions[0].seed.r, 0.0, 1e-12);
  EXPECT_TRUE(c.fluid.empty());  // no gap region, no [case] fluid
}
