// Triangle area, signed area and centroid of mesh/triangle.hpp.

#include <gtest/gtest.h>

#include "mesh/triangle.hpp"

using rheomag::mesh::Point;

TEST(Triangle, SignedAreaFollowsTheOrientation) {
  const Point a{0.0, 0.0}, b{2.0, 0.0}, c{0.0, 1.0};
  EXPECT_EQ(rheomag::mesh::signed_triangle_area(a, b, c), 1.0);
  EXPECT_EQ(rheomag::mesh::signed_triangle_area(a, c, b), -1.0);
  EXPECT_EQ(rheomag::mesh::triangle_area(a, c, b), 1.0);
}

TEST(Triangle, AreaIsTheWrittenOutFormulaBitForBit) {
  const Point a{0.0123, 0.4567}, b{0.0891, 0.1234}, c{0.3456, 0.789};
  const double written = 0.5 * std::abs((b.r - a.r) * (c.z - a.z) - (c.r - a.r) * (b.z - a.z));
  EXPECT_EQ(rheomag::mesh::triangle_area(a, b, c), written);
}

TEST(Triangle, CentroidIsTheMeanOfTheVertices) {
  const Point g = rheomag::mesh::triangle_centroid({0.0, 0.0}, {3.0, 0.0}, {0.0, 6.0});
  EXPECT_EQ(g.r, 1.0);
  EXPECT_EQ(g.z, 2.0);
}
