// The swept mesher (meridian triangles x graded angles, prisms split into tetrahedra): a
// conforming mesh, and on the bundled annular valve the 2D solution within 1 % (the issue's
// target): the wedge model, and a half model whose "slot" is filled with the core's own steel
// (an axisymmetric body on the 3D mesh a lead slot gets: long prisms, graded angles).
// Reference: rheomag's 2D P2 solver on the same case (docs/validation.md).

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numbers>
#include <string>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "magnetostatics/domain.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "magnetostatics3d/solve3d.hpp"
#include "magnetostatics3d/swept_mesh.hpp"
#include "mesh/mesher.hpp"
#include "mesh/triangle.hpp"

namespace rheomag::magnetostatics3d {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

const bool kLaterSectionsRegistered = cases::register_case_section("valve") &&
                                      cases::register_case_section("damper") &&
                                      cases::register_case_section("fluid");

cases::Case annular_valve(const std::string& features = "") {
  const std::string path = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";
  return cases::parse_case(cases::read_input_file(path) + features, path);
}

TEST(SweptMesh, GradedAnglesAreFineAtTheWallsAndCoarseAway) {
  const double fine = 2 * kDeg, coarse = 10 * kDeg;
  const Revolution rev =
      graded_revolution(std::numbers::pi, {4 * kDeg, 90 * kDeg}, fine, coarse, 1.5);
  EXPECT_FALSE(rev.full);
  EXPECT_DOUBLE_EQ(rev.angles.front(), 0.0);
  EXPECT_DOUBLE_EQ(rev.angles.back(), std::numbers::pi);
  for (double wall : {4 * kDeg, 90 * kDeg}) {
    const auto it = std::find_if(rev.angles.begin(), rev.angles.end(),
                                 [&](double a) { return std::abs(a - wall) < 1e-12; });
    ASSERT_NE(it, rev.angles.end()) << wall;
    // The steps on both sides of a wall are fine (within the rescaling of an interval).
    if (it != rev.angles.begin()) {
      EXPECT_LT(*it - *(it - 1), 1.5 * fine);
    }
    EXPECT_LT(*(it + 1) - *it, 1.5 * fine);
  }
  for (std::size_t k = 1; k < rev.angles.size(); ++k) {
    EXPECT_GT(rev.angles[k] - rev.angles[k - 1], 0.5 * fine);
    EXPECT_LT(rev.angles[k] - rev.angles[k - 1], 1.5 * coarse);
  }
  // Far fewer steps than a uniform fine revolution.
  EXPECT_LT(rev.angles.size(), 40u);
}

// Conformity: every face of the swept mesh is shared by two tetrahedra or lies on the boundary
// of the closed domain, where it carries a condition (outer or symmetry); the volume is that of
// the facetted revolved body (the prisms' chords), and every tetrahedron is positive.
TEST(SweptMesh, ConformingWithEveryBoundaryFaceClassified) {
  const cases::Problem closed = magnetostatics::close_domain(annular_valve().problem);
  mesh::MeshOptions options;
  options.order = 1;
  options.min_gap_elements = 1;
  const mesh::Mesh meridian = mesh::generate_mesh(closed.geometry, options);
  for (double span : {std::numbers::pi, 2 * std::numbers::pi}) {
    const Revolution rev = graded_revolution(span, {0.3}, 3 * kDeg, 30 * kDeg, 2.0);
    const TetMesh m = sweep_mesh(meridian, rev);
    std::map<std::array<int, 3>, int> count;
    double volume = 0.0;
    for (std::size_t t = 0; t < m.tets.size(); ++t) {
      EXPECT_GT(m.volume(static_cast<int>(t)), 0.0);
      volume += m.volume(static_cast<int>(t));
      for (int skip = 0; skip < 4; ++skip) {
        std::array<int, 3> f{};
        for (int k = 0, n = 0; k < 4; ++k)
          if (k != skip) f[n++] = m.tets[t][k];
        std::sort(f.begin(), f.end());
        ++count[f];
      }
    }
    std::size_t boundary = 0;
    for (const auto& [f, n] : count) {
      EXPECT_LE(n, 2);
      boundary += n == 1;
    }
    EXPECT_EQ(boundary, m.faces.size()) << span;
    // Exact volume of the facetted body: each triangle's prism ring is the triangle's meridian
    // area times sum over intervals of (sin(step) / step) x 2 pi-like length: Pappus per wedge.
    double expected = 0.0;
    for (const auto& tri : meridian.triangles) {
      const mesh::Point& a = meridian.nodes[tri[0]];
      const mesh::Point& b = meridian.nodes[tri[1]];
      const mesh::Point& c = meridian.nodes[tri[2]];
      const double area = mesh::triangle_area(a, b, c);
      double chord = 0.0;  // sum of sin(step) over the intervals
      for (std::size_t k = 1; k < rev.angles.size(); ++k)
        chord += std::sin(rev.angles[k] - rev.angles[k - 1]);
      expected += area * (a.r + b.r + c.r) / 3.0 * chord;
    }
    EXPECT_NEAR(volume / expected, 1.0, 1e-9) << span;
  }
}

// restore_ring_areas: with equal steps the factors scale x and y by sqrt(d / sin d), so the
// facetted body gets exactly the volume of the true revolved body (Pappus: meridian area x
// centroid radius x span); with graded steps (3 to 30 degrees, where the factors change from
// one angle to the next) at least nine tenths of the chords' deficit are restored (measured:
// -0.05 % left for the half, -0.17 % for the full revolution).
TEST(SweptMesh, RestoredRingsHaveTheTrueRevolvedVolume) {
  const cases::Problem closed = magnetostatics::close_domain(annular_valve().problem);
  mesh::MeshOptions options;
  options.order = 1;
  options.min_gap_elements = 1;
  const mesh::Mesh meridian = mesh::generate_mesh(closed.geometry, options);
  double pappus = 0.0;  // per radian
  for (const auto& tri : meridian.triangles) {
    const mesh::Point& a = meridian.nodes[tri[0]];
    const mesh::Point& b = meridian.nodes[tri[1]];
    const mesh::Point& c = meridian.nodes[tri[2]];
    const double area = mesh::triangle_area(a, b, c);
    pappus += area * (a.r + b.r + c.r) / 3.0;
  }
  const std::vector<std::pair<Revolution, bool>> cases{
      {make_revolution(std::numbers::pi, 15 * kDeg), true},
      {make_revolution(2 * std::numbers::pi, 15 * kDeg), true},
      {graded_revolution(std::numbers::pi, {0.3}, 3 * kDeg, 30 * kDeg, 2.0), false},
      {graded_revolution(2 * std::numbers::pi, {0.3, 2.0}, 3 * kDeg, 30 * kDeg, 2.0), false}};
  for (const auto& [rev, equal_steps] : cases) {
    TetMesh m = sweep_mesh(meridian, rev);
    auto volume = [&] {
      double v = 0.0;
      for (std::size_t t = 0; t < m.tets.size(); ++t) v += m.volume(static_cast<int>(t));
      return v;
    };
    const double span = rev.angles.back() - rev.angles.front();
    const double deficit = 1.0 - volume() / (pappus * span);  // the chords'
    EXPECT_GT(deficit, 1e-3);
    const std::vector<Eigen::Vector3d> swept = m.nodes;
    restore_ring_areas(m.nodes, swept, rev);
    EXPECT_NEAR(volume() / (pappus * span), 1.0, equal_steps ? 1e-9 : 0.1 * deficit)
        << rev.angles.size();
  }
}

// The axisymmetric annular valve: wedge model on the swept mesh, 2D within 1 % (gap |B| and
// flux linkage), as for the TetGen wedge (test_revolved_valves.cpp), at three layers across the
// gap and regions at 0.15 of their side (at swept_options()' 2 and 0.25 the flux linkage is
// -1.0 %, the gap |B| +0.2 %: first-order elements converge slowly in lambda).
TEST(SweptMesh, AnnularValveWedgeMatches2dWithinOnePercent) {
  const cases::Case c = annular_valve();
  const magnetostatics::SolveResult two = magnetostatics::solve_problem(c.problem);
  Solve3dOptions options = swept_options();
  options.gap_layers = 3;
  options.region_fraction = 0.15;
  const Solve3dResult three = solve_problem_3d(c.problem, {}, options);
  EXPECT_EQ(three.results.part, ModelPart::wedge);
  ASSERT_EQ(three.results.gaps.size(), two.results.gaps.size());
  for (std::size_t g = 0; g < two.results.gaps.size(); ++g)
    EXPECT_NEAR(three.results.gaps[g].b.average / two.results.gaps[g].b.average, 1.0, 0.01);
  EXPECT_NEAR(three.results.circuits[0].flux_linkage / two.results.circuits[0].flux_linkage, 1.0,
              0.01);
}

// Half model of the lead-slot mesh with the slot filled by the core's steel (the body stays
// axisymmetric): every 10-degree sector of both gaps and the flux linkage within 1 % of 2D
// (the target), with swept_options() (15-degree steps, 3 degrees at the slot's edges,
// growth 2; 3 layers across a gap, regions at 0.2 of their side; rings restored to their true
// areas). Measured: sectors +0.07 ... +0.77 %, lambda -0.67 % (351k tetrahedra); without
// restore_ring_areas lambda loses the chords' O(step^2) area (docs/magnetostatics3d.md).
TEST(SweptMesh, SteelFilledSlotHalfModelMatches2dInEverySector) {
  const cases::Case c = annular_valve(
      "\n[[feature]]\nkind = \"lead_slot\"\nregion = \"core\"\nwidth = 3.0\ndepth = 2.0\n"
      "material = \"AISI 1010\"\n");
  const magnetostatics::SolveResult two = magnetostatics::solve_problem(c.problem);
  const Solve3dResult three = solve_problem_3d(c.problem, read_features(c), swept_options());
  EXPECT_EQ(three.results.part, ModelPart::half);
  ASSERT_EQ(three.results.gaps.size(), two.results.gaps.size());
  for (std::size_t g = 0; g < two.results.gaps.size(); ++g) {
    for (int k = 0; k < kThetaSectors; ++k) {
      EXPECT_NEAR(three.results.gaps[g].b_avg_theta[k] / two.results.gaps[g].b.average, 1.0, 0.01)
          << three.results.gaps[g].name << " sector " << k;
    }
  }
  EXPECT_NEAR(three.results.circuits[0].flux_linkage / two.results.circuits[0].flux_linkage, 1.0,
              0.01);
}

}  // namespace
}  // namespace rheomag::magnetostatics3d
