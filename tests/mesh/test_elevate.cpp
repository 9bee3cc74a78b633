// elevate_to_p2: one node per edge, at its exact midpoint, shared by the two triangles of an edge.

#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <set>
#include <utility>

#include "mesh/elevate.hpp"
#include "mesh/mesher.hpp"
#include "pslg_fixtures.hpp"

namespace rheomag::mesh {
namespace {

Mesh linear_valve() {
  MeshOptions options;
  options.order = 1;
  return generate_mesh(fixtures::valve_like_pslg(), options);
}

TEST(ElevateToP2, MidpointsAreExactAndSharedBetweenNeighbours) {
  const Mesh linear = linear_valve();
  const Mesh quadratic = elevate_to_p2(linear);
  ASSERT_EQ(quadratic.order, 2);
  EXPECT_EQ(quadratic.nodes_per_triangle(), 6);
  EXPECT_EQ(quadratic.vertex_count, linear.vertex_count);
  ASSERT_EQ(quadratic.triangles.size(), linear.triangles.size());

  std::set<std::pair<int, int>> edges;
  std::map<std::pair<int, int>, int> midpoint_of;
  for (std::size_t t = 0; t < quadratic.triangles.size(); ++t) {
    const auto& tri = quadratic.triangles[t];
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(tri[k], linear.triangles[t][k]);  // vertices unchanged
      const int a = tri[k], b = tri[(k + 1) % 3], m = tri[3 + k];
      ASSERT_GE(m, quadratic.vertex_count);
      // Exact: the midpoint is computed as 0.5 * (a + b) in double, as here.
      EXPECT_EQ(quadratic.nodes[m].r, 0.5 * (quadratic.nodes[a].r + quadratic.nodes[b].r));
      EXPECT_EQ(quadratic.nodes[m].z, 0.5 * (quadratic.nodes[a].z + quadratic.nodes[b].z));
      auto [it, inserted] = midpoint_of.try_emplace(std::minmax(a, b), m);
      EXPECT_EQ(it->second, m) << "edge " << a << "-" << b << " has two midpoint nodes";
      edges.insert(std::minmax(a, b));
    }
  }
  // One new node per edge, no unused node.
  EXPECT_EQ(quadratic.nodes.size(), linear.nodes.size() + edges.size());
  std::set<int> midpoints;
  for (const auto& [edge, m] : midpoint_of) midpoints.insert(m);
  EXPECT_EQ(midpoints.size(), edges.size());

  ASSERT_EQ(quadratic.boundary_edges.size(), linear.boundary_edges.size());
  ASSERT_FALSE(quadratic.boundary_edges.empty());
  for (const BoundaryEdge& e : quadratic.boundary_edges)
    EXPECT_EQ(e.nodes[2], midpoint_of.at(std::minmax(e.nodes[0], e.nodes[1])));
}

TEST(ElevateToP2, OrderTwoOptionEqualsElevatingTheLinearMesh) {
  const Mesh direct = generate_mesh(fixtures::valve_like_pslg(), MeshOptions{});  // default P2
  const Mesh elevated = elevate_to_p2(linear_valve());
  ASSERT_EQ(direct.order, 2);
  EXPECT_EQ(direct.triangles, elevated.triangles);
  ASSERT_EQ(direct.nodes.size(), elevated.nodes.size());
  for (std::size_t i = 0; i < direct.nodes.size(); ++i) {
    EXPECT_EQ(direct.nodes[i].r, elevated.nodes[i].r);
    EXPECT_EQ(direct.nodes[i].z, elevated.nodes[i].z);
  }
  const Mesh twice = elevate_to_p2(elevated);  // already quadratic: unchanged
  EXPECT_EQ(twice.triangles, elevated.triangles);
}

}  // namespace
}  // namespace rheomag::mesh
