// Contour lines of a uniform planar field (A_z linear in x and y: B uniform) on an irregular
// triangle mesh must be straight, parallel and equally spaced: every segment lies on its level's
// line n . p = c (to 1e-9 mm, rounding only), and each level's pieces add up to the full chord
// across the square (to 1e-9 relative: no piece missing or doubled).

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "plot/triangle_field.hpp"

using namespace rheomag::plot;

namespace {

/// A 24 x 24 square grid over [0, 10]^2 mm with its interior points moved irregularly (by up to
/// 0.3 of a cell) and each cell split along alternating diagonals.
TriangleMesh irregular_square() {
  const int n = 24;
  const double h = 10.0 / n;
  TriangleMesh mesh;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const bool interior = i > 0 && i < n && j > 0 && j < n;
      const double dx = interior ? 0.3 * h * std::sin(1.7 * i + 2.3 * j) : 0.0;
      const double dy = interior ? 0.3 * h * std::cos(2.9 * i - 1.1 * j) : 0.0;
      mesh.points.push_back({i * h + dx, j * h + dy});
    }
  }
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if ((i + j) % 2 == 0) {
        mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        mesh.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  }
  return mesh;
}

}  // namespace

TEST(Contour, UniformPlanarFieldGivesStraightParallelEquallySpacedLines) {
  const TriangleMesh mesh = irregular_square();
  // A_z = 0.3 x + 0.1 y [any unit]: B = (dA/dy, -dA/dx) is uniform; lines of A_z are flux lines.
  const double gx = 0.3, gy = 0.1, g = std::hypot(gx, gy);
  std::vector<double> a;
  for (const auto& p : mesh.points) a.push_back(gx * p[0] + gy * p[1]);
  const std::vector<double> levels = centred_levels(0.0, gx * 10.0 + gy * 10.0, 12);
  const auto segments = contour_segments(mesh, a, levels);
  ASSERT_FALSE(segments.empty());
  std::map<int, double> length;
  for (const ContourSegment& s : segments) {
    for (const auto& p : {s.a, s.b}) {
      // Distance from its level's line, in mm.
      EXPECT_NEAR((gx * p[0] + gy * p[1] - levels[s.level]) / g, 0.0, 1e-9);
    }
    // Direction perpendicular to the gradient: parallel to every other line.
    const double dx = s.b[0] - s.a[0], dy = s.b[1] - s.a[1];
    const double l = std::hypot(dx, dy);
    if (l > 1e-9) {
      EXPECT_NEAR((dx * gx + dy * gy) / (l * g), 0.0, 1e-9);
    }
    length[s.level] += l;
  }
  ASSERT_EQ(length.size(), levels.size());
  // Equal spacing: neighbouring levels' lines are (level step) / |grad A| apart.
  const double spacing = (levels[1] - levels[0]) / g;
  for (std::size_t k = 1; k < levels.size(); ++k)
    EXPECT_NEAR((levels[k] - levels[k - 1]) / g, spacing, 1e-12 * spacing);
  // Continuous lines: each level's pieces cover its chord of the square [0, 10]^2 exactly.
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const double c = levels[k];
    // The line 0.3 x + 0.1 y = c clipped to the square: param by x, y = (c - 0.3 x) / 0.1.
    double x0 = std::max(0.0, (c - gy * 10.0) / gx), x1 = std::min(10.0, c / gx);
    const double chord = (x1 - x0) * std::hypot(1.0, gx / gy);
    EXPECT_NEAR(length[static_cast<int>(k)], chord, 1e-9 * chord) << "level " << k;
  }
}

TEST(Contour, LevelOutsideTheFieldGivesNoSegment) {
  const TriangleMesh mesh = irregular_square();
  std::vector<double> a(mesh.points.size(), 1.0);
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = 1.0 + 0.01 * mesh.points[i][0];
  EXPECT_TRUE(contour_segments(mesh, a, {0.5, 2.5}).empty());
}
