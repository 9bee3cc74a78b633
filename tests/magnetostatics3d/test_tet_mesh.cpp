// TetGen meshing, edges and the tree-cotree gauge on small domains.

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "magnetostatics3d/gauge.hpp"
#include "magnetostatics3d/plc.hpp"

namespace rheomag::magnetostatics3d {
namespace {

/// The unit cube as a PLC; its faces carry `kind`.
Plc cube(FaceKind kind) {
  Plc plc;
  plc.source = "cube";
  for (int i = 0; i < 8; ++i) plc.points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const int faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  for (const auto& f : faces) plc.facets.push_back({{{f[0], f[1], f[2], f[3]}}, kind});
  plc.regions.push_back({Eigen::Vector3d(0.5, 0.5, 0.5), 0, 0.001});
  return plc;
}

TEST(TetMesh, CubeVolumeEdgesAndEulerCharacteristic) {
  const TetMesh m = tetrahedralize(cube(FaceKind::outer));
  double volume = 0.0;
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t) {
    EXPECT_GT(m.volume(t), 0.0);
    volume += m.volume(t);
  }
  EXPECT_NEAR(volume, 1.0, 1e-12);
  // Face count from Euler's formula for a ball: V - E + F - T = 1.
  const long faces = 1 - static_cast<long>(m.nodes.size()) + static_cast<long>(m.edges.size()) +
                     static_cast<long>(m.tets.size());
  EXPECT_EQ(4 * static_cast<long>(m.tets.size()), 2 * faces - static_cast<long>(m.faces.size()));
}

// Gauge: the tree holds one edge per interior node (all boundary nodes are one fixed node), so
// the unknowns are the interior edges not in it; the Whitney curls of every tet sum with the
// edge-gradient incidence to zero (curl grad = 0 exactly).
TEST(TetMesh, TreeCotreeRemovesOneEdgePerInteriorNode) {
  const TetMesh m = tetrahedralize(cube(FaceKind::outer));
  const EdgeDofs d = tree_cotree_dofs(m);
  std::vector<bool> boundary(m.nodes.size(), false);
  for (const auto& f : m.faces)
    for (int v : f) boundary[v] = true;
  int interior = 0, fixed = 0;
  for (bool b : boundary) interior += b ? 0 : 1;
  for (bool f : d.fixed) fixed += f ? 1 : 0;
  EXPECT_EQ(d.tree_edges, interior);
  EXPECT_EQ(d.free_count() + d.tree_edges + fixed, static_cast<int>(m.edges.size()));
  for (int t = 0; t < static_cast<int>(m.tets.size()); t += 97) {
    const auto c = edge_curls(m, t);
    for (int node = 0; node < 4; ++node) {
      // grad(lambda_node) as edge values: +1 on edges leaving the node towards higher index...
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (int e = 0; e < 6; ++e) {
        const int a = kTetEdges[e][0], b = kTetEdges[e][1];
        const double along = (b == node) - (a == node);  // d(lambda_node) along local a -> b
        sum += along * edge_sign(m, t, e) * c[e];
      }
      EXPECT_LT(sum.norm(), 1e-9 * c[0].norm() + 1e-300);
    }
  }
}

TEST(TetMesh, SelfIntersectingFacetsAreInputErrors) {
  Plc plc = cube(FaceKind::outer);
  // A triangle piercing the cube's top face.
  plc.points.emplace_back(0.5, 0.5, 0.5);
  plc.points.emplace_back(0.2, 0.5, 1.5);
  plc.points.emplace_back(0.8, 0.5, 1.5);
  plc.facets.push_back({{{8, 9, 10}}, FaceKind::interior});
  try {
    tetrahedralize(plc);
    FAIL() << "TetGen accepted intersecting facets";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cube: the tetrahedral mesher (TetGen) failed"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace rheomag::magnetostatics3d
