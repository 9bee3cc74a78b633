// Fixed-topology morphing: piecewise-linear node maps between breakpoints, inversion detection.

#include <gtest/gtest.h>

#include "design/morph_mesh.hpp"

namespace {

using rheomag::design::Breakpoints;
using rheomag::design::morph_mesh;
using rheomag::mesh::Mesh;

// A P1 mesh of the square [0, 2] x [0, 2] on a 3 x 3 node grid (spacing 1), 8 triangles.
Mesh grid_mesh() {
  Mesh m;
  m.order = 1;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) m.nodes.push_back({double(i), double(j)});
  m.vertex_count = 9;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int a = j * 3 + i, b = a + 1, c = a + 4, d = a + 3;
      m.triangles.push_back({a, b, c, -1, -1, -1});
      m.triangles.push_back({a, c, d, -1, -1, -1});
      m.region.push_back(0);
      m.region.push_back(0);
    }
  return m;
}

TEST(OptimiseMorph, IdentityKeepsNodes) {
  const Mesh m = grid_mesh();
  const Breakpoints b{{0.0, 1.0, 2.0}, {0.0, 1.0, 2.0}};
  const auto out = morph_mesh(m, b, b);
  ASSERT_TRUE(out);
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    EXPECT_DOUBLE_EQ(out->nodes[i].r, m.nodes[i].r);
    EXPECT_DOUBLE_EQ(out->nodes[i].z, m.nodes[i].z);
  }
}

// Breakpoint r = 1 -> 1.5 (z = 1 -> 0.5): nodes on it follow, nodes on fixed breakpoints stay;
// a node between two breakpoints would move in proportion (exact piecewise-linear map).
TEST(OptimiseMorph, NodesFollowTheirBreakpoints) {
  const Mesh m = grid_mesh();
  const auto out =
      morph_mesh(m, {{0.0, 1.0, 2.0}, {0.0, 1.0, 2.0}}, {{0.0, 1.5, 2.0}, {0.0, 0.5, 2.0}});
  ASSERT_TRUE(out);
  EXPECT_DOUBLE_EQ(out->nodes[4].r, 1.5);  // centre node
  EXPECT_DOUBLE_EQ(out->nodes[4].z, 0.5);
  EXPECT_DOUBLE_EQ(out->nodes[8].r, 2.0);
  EXPECT_DOUBLE_EQ(out->nodes[0].z, 0.0);
}

// Inner breakpoints only (the mesh reaches beyond them): the outer part stretches, the mesh's
// extent stays.
TEST(OptimiseMorph, OuterExtentStaysFixed) {
  const Mesh m = grid_mesh();
  const auto out = morph_mesh(m, {{0.0, 1.0}, {0.0, 1.0}}, {{0.0, 1.4}, {0.0, 0.8}});
  ASSERT_TRUE(out);
  EXPECT_DOUBLE_EQ(out->nodes[4].r, 1.4);
  EXPECT_DOUBLE_EQ(out->nodes[4].z, 0.8);
  EXPECT_DOUBLE_EQ(out->nodes[8].r, 2.0);
  EXPECT_DOUBLE_EQ(out->nodes[8].z, 2.0);
}

TEST(OptimiseMorph, RefusesInversionCrossingAndCountChange) {
  const Mesh m = grid_mesh();
  // The inner breakpoint pushed past the mesh's extent: elements would invert.
  EXPECT_FALSE(morph_mesh(m, {{0.0, 1.0}, {0.0, 1.0}}, {{0.0, 2.5}, {0.0, 1.0}}));
  // Breakpoints crossing each other.
  EXPECT_FALSE(morph_mesh(m, {{0.0, 1.0, 2.0}, {0.0, 2.0}}, {{0.0, 2.0, 1.0}, {0.0, 2.0}}));
  // A different number of breakpoints: another topology.
  EXPECT_FALSE(morph_mesh(m, {{0.0, 1.0, 2.0}, {0.0, 2.0}}, {{0.0, 2.0}, {0.0, 2.0}}));
}

}  // namespace
