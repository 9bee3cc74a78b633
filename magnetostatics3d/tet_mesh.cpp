#include "magnetostatics3d/tet_mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace rheomag::magnetostatics3d {

void TetMesh::build_edges() {
  // Sort all (lower, higher) local edges once; equal pairs are one global edge.
  std::vector<std::array<long long, 2>> keyed;  // (key, tet * 6 + local)
  keyed.reserve(tets.size() * 6);
  const long long n = static_cast<long long>(nodes.size());
  for (std::size_t t = 0; t < tets.size(); ++t) {
    for (int e = 0; e < 6; ++e) {
      long long a = tets[t][kTetEdges[e][0]], b = tets[t][kTetEdges[e][1]];
      if (a > b) std::swap(a, b);
      keyed.push_back({a * n + b, static_cast<long long>(t) * 6 + e});
    }
  }
  std::sort(keyed.begin(), keyed.end());
  edges.clear();
  tet_edges.assign(tets.size(), {});
  for (std::size_t i = 0; i < keyed.size(); ++i) {
    if (i == 0 || keyed[i][0] != keyed[i - 1][0]) {
      edges.push_back({static_cast<int>(keyed[i][0] / n), static_cast<int>(keyed[i][0] % n)});
    }
    tet_edges[keyed[i][1] / 6][keyed[i][1] % 6] = static_cast<int>(edges.size()) - 1;
  }
}

double TetMesh::volume(int t) const {
  const auto& v = tets[t];
  return (nodes[v[1]] - nodes[v[0]])
             .dot((nodes[v[2]] - nodes[v[0]]).cross(nodes[v[3]] - nodes[v[0]])) /
         6.0;
}

std::array<Eigen::Vector3d, 4> TetMesh::gradients(int t) const {
  const auto& v = tets[t];
  Eigen::Matrix3d d;
  d.col(0) = nodes[v[1]] - nodes[v[0]];
  d.col(1) = nodes[v[2]] - nodes[v[0]];
  d.col(2) = nodes[v[3]] - nodes[v[0]];
  // lambda_{1,2,3} = D^-1 (x - x0) row-wise; lambda_0 = 1 - the others.
  const Eigen::Matrix3d inv = d.inverse();
  std::array<Eigen::Vector3d, 4> g;
  for (int i = 0; i < 3; ++i) g[i + 1] = inv.row(i).transpose();
  g[0] = -(g[1] + g[2] + g[3]);
  return g;
}

Eigen::Vector3d TetMesh::centroid(int t) const {
  const auto& v = tets[t];
  return 0.25 * (nodes[v[0]] + nodes[v[1]] + nodes[v[2]] + nodes[v[3]]);
}

std::array<Eigen::Vector3d, 6> edge_curls(const TetMesh& m, int t) {
  const auto g = m.gradients(t);
  std::array<Eigen::Vector3d, 6> c;
  for (int e = 0; e < 6; ++e) {
    c[e] = 2.0 * edge_sign(m, t, e) * g[kTetEdges[e][0]].cross(g[kTetEdges[e][1]]);
  }
  return c;
}

}  // namespace rheomag::magnetostatics3d
