#pragma once
// Test helper: structured P1/P2 triangle meshes of a rectangle in the (r, z) plane.

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include "mesh/mesh.hpp"

namespace rheomag::test {

/// n + 1 equally spaced values from a to b.
inline std::vector<double> uniform(double a, double b, int n) {
  std::vector<double> x(n + 1);
  for (int i = 0; i <= n; ++i) x[i] = a + (b - a) * i / n;
  return x;
}

/// Concatenates coordinate lists, dropping the duplicated joints.
inline std::vector<double> join(std::vector<double> a, const std::vector<double>& b) {
  for (double x : b) {
    if (a.empty() || x > a.back() + 1e-15) a.push_back(x);
  }
  return a;
}

/// n + 1 values from a to b whose spacing grows geometrically by `ratio` per cell.
inline std::vector<double> graded(double a, double b, int n, double ratio) {
  std::vector<double> x(n + 1);
  double total = 0.0, h = 1.0;
  for (int i = 0; i < n; ++i, h *= ratio) total += h;
  x[0] = a;
  h = (b - a) / total;
  for (int i = 1; i <= n; ++i, h *= ratio) x[i] = x[i - 1] + h;
  x[n] = b;
  return x;
}

/// Tensor-product mesh of [r.front(), r.back()] x [z.front(), z.back()], each cell cut into two
/// counter-clockwise triangles. `region(r, z)` gives the region of a triangle from its centroid.
/// side_marker = boundary marker of the sides {r = r0, r = r1, z = z0, z = z1} (-1 = none).
inline mesh::Mesh structured_mesh(const std::vector<double>& r, const std::vector<double>& z,
                                  int order, const std::function<int(double, double)>& region,
                                  std::array<int, 4> side_marker = {-1, -1, -1, -1}) {
  mesh::Mesh m;
  m.order = order;
  const int nr = static_cast<int>(r.size()), nz = static_cast<int>(z.size());
  for (int j = 0; j < nz; ++j) {
    for (int i = 0; i < nr; ++i) m.nodes.push_back({r[i], z[j]});
  }
  m.vertex_count = static_cast<int>(m.nodes.size());
  auto vertex = [&](int i, int j) { return j * nr + i; };
  std::map<std::pair<int, int>, int> midpoint;
  auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    auto it = midpoint.find(key);
    if (it != midpoint.end()) return it->second;
    const int id = static_cast<int>(m.nodes.size());
    m.nodes.push_back({0.5 * (m.nodes[a].r + m.nodes[b].r), 0.5 * (m.nodes[a].z + m.nodes[b].z)});
    midpoint.emplace(key, id);
    return id;
  };
  auto add = [&](int a, int b, int c) {
    std::array<int, 6> t{a, b, c, -1, -1, -1};
    if (order == 2) t[3] = mid(a, b), t[4] = mid(b, c), t[5] = mid(c, a);
    m.triangles.push_back(t);
    const auto &pa = m.nodes[a], &pb = m.nodes[b], &pc = m.nodes[c];
    m.region.push_back(region((pa.r + pb.r + pc.r) / 3.0, (pa.z + pb.z + pc.z) / 3.0));
  };
  for (int j = 0; j + 1 < nz; ++j) {
    for (int i = 0; i + 1 < nr; ++i) {
      add(vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1));
      add(vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1));
    }
  }
  auto edge = [&](int a, int b, int marker) {
    if (marker < 0) return;
    mesh::BoundaryEdge e;
    e.nodes = {a, b, order == 2 ? mid(a, b) : -1};
    e.boundary = marker;
    m.boundary_edges.push_back(e);
  };
  for (int j = 0; j + 1 < nz; ++j) {
    edge(vertex(0, j), vertex(0, j + 1), side_marker[0]);
    edge(vertex(nr - 1, j), vertex(nr - 1, j + 1), side_marker[1]);
  }
  for (int i = 0; i + 1 < nr; ++i) {
    edge(vertex(i, 0), vertex(i + 1, 0), side_marker[2]);
    edge(vertex(i, nz - 1), vertex(i + 1, nz - 1), side_marker[3]);
  }
  return m;
}

}  // namespace rheomag::test
