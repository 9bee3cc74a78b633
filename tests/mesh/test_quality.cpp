// measure_quality / band_thickness on meshes with hand-computed statistics.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesh/quality.hpp"

namespace rheomag::mesh {
namespace {

/// The unit square split along its diagonal into two right isosceles triangles, in two regions.
Mesh two_triangles() {
  Mesh mesh;
  mesh.nodes = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.triangles = {{0, 1, 2, -1, -1, -1}, {0, 2, 3, -1, -1, -1}};
  mesh.region = {0, 1};
  mesh.vertex_count = 4;
  return mesh;
}

// Reference: right isosceles triangle with legs 1: angles 45/45/90 deg; aspect ratio
// L P / (4 sqrt(3) A) = sqrt(2) (2 + sqrt(2)) / (2 sqrt(3)) = (1 + sqrt(2)) / sqrt(3).
TEST(MeshQuality, RightIsoscelesTriangles) {
  Pslg pslg;
  pslg.regions = {{{0.7, 0.3}, "lower", 0.0, GapKind::none, false},
                  {{0.3, 0.7}, "upper", 0.0, GapKind::radial, false}};
  const MeshQuality q = measure_quality(two_triangles(), pslg);
  EXPECT_EQ(q.elements, 2);
  EXPECT_EQ(q.nodes, 4);
  EXPECT_NEAR(q.min_angle, 45.0, 1e-12);
  EXPECT_NEAR(q.max_aspect_ratio, (1.0 + std::sqrt(2.0)) / std::sqrt(3.0), 1e-12);
  ASSERT_EQ(q.regions.size(), 2u);
  EXPECT_EQ(q.regions[1].name, "upper");
  EXPECT_EQ(q.regions[0].elements, 1);
  EXPECT_NEAR(q.regions[0].area, 0.5, 1e-15);
  EXPECT_NEAR(q.regions[1].max_edge, std::sqrt(2.0), 1e-15);
  // Each region's perimeter is 2 + sqrt(2) (the diagonal separates them).
  EXPECT_NEAR(q.regions[1].thickness, band_thickness(0.5, 2.0 + std::sqrt(2.0)), 1e-15);
  const std::string text = format_quality(q);
  EXPECT_NE(text.find("upper"), std::string::npos) << text;
  EXPECT_NE(text.find("radial gap"), std::string::npos) << text;
  EXPECT_NE(text.find("min angle 45.00 deg"), std::string::npos) << text;
}

// Reference: a t x L rectangle has A = t L, P = 2 (t + L): the smaller root is t exactly; a
// disc of radius R (no real root) gives 4A/P = 2R, its diameter. Tolerance: rounding.
TEST(BandThickness, RectangleAndDisc) {
  EXPECT_NEAR(band_thickness(1e-3 * 40e-3, 2 * (1e-3 + 40e-3)), 1e-3, 1e-15);
  EXPECT_NEAR(band_thickness(3.0 * 3.0, 12.0), 3.0, 1e-12);  // square: both roots equal
  const double r = 0.01;
  EXPECT_NEAR(band_thickness(std::numbers::pi * r * r, 2 * std::numbers::pi * r), 2 * r, 1e-15);
}

}  // namespace
}  // namespace rheomag::mesh
