#pragma once
// Test geometries for the mesher: a small builder and a few PSLGs with known areas.

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/pslg.hpp"

namespace rheomag::mesh::fixtures {

/// Builds a PSLG from closed polygons; equal points are shared.
class PslgBuilder {
 public:
  /// Index of the point (r, z), added if new.
  int point(double r, double z) {
    auto [it, inserted] = index_.try_emplace({r, z}, static_cast<int>(pslg.points.size()));
    if (inserted) pslg.points.push_back({r, z});
    return it->second;
  }
  /// Adds the closed polygon through `corners` with one boundary marker on all its sides.
  void polygon(const std::vector<Point>& corners, int boundary = -1) {
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const Point& a = corners[i];
      const Point& b = corners[(i + 1) % corners.size()];
      pslg.segments.push_back({point(a.r, a.z), point(b.r, b.z), boundary, 0.0});
    }
  }
  /// Adds the axis-aligned rectangle [r0, r1] x [z0, z1].
  void rectangle(double r0, double z0, double r1, double z1, int boundary = -1) {
    polygon({{r0, z0}, {r1, z0}, {r1, z1}, {r0, z1}}, boundary);
  }
  /// Adds a regular n-gon of circumradius `radius` centred at (r, z).
  void ngon(double r, double z, double radius, int n, int boundary = -1) {
    std::vector<Point> corners;
    for (int k = 0; k < n; ++k) {
      const double a = 2.0 * std::numbers::pi * k / n;
      corners.push_back({r + radius * std::cos(a), z + radius * std::sin(a)});
    }
    polygon(corners, boundary);
  }
  /// Adds a region seed; returns its index.
  int region(double r, double z, std::string name, double mesh_size = 0.0,
             GapKind gap = GapKind::none, bool hole = false) {
    pslg.regions.push_back({{r, z}, std::move(name), mesh_size, gap, hole});
    return static_cast<int>(pslg.regions.size()) - 1;
  }

  Pslg pslg;

 private:
  std::map<std::pair<double, double>, int> index_;
};

/// Area of a regular n-gon of circumradius R: (n/2) R^2 sin(2 pi / n).
inline double ngon_area(double radius, int n) {
  return 0.5 * n * radius * radius * std::sin(2.0 * std::numbers::pi / n);
}

/// A valve-like axisymmetric geometry [m]: steel core with a coil pocket, a 1 mm annular fluid
/// gap, a steel housing, all in an air box whose outer sides carry boundary marker 0.
inline Pslg valve_like_pslg(double core_size = 0.0) {
  PslgBuilder b;
  b.rectangle(0.0, -0.05, 0.05, 0.05);        // air box
  b.rectangle(0.0, -0.02, 0.0195, 0.02);      // core
  b.rectangle(0.012, -0.008, 0.0195, 0.008);  // coil pocket (on the core's outer side)
  b.rectangle(0.0195, -0.02, 0.0205, 0.02);   // annular gap
  b.rectangle(0.0205, -0.02, 0.025, 0.02);    // housing
  for (auto& s : b.pslg.segments) {
    const Point& p = b.pslg.points[s.a];
    const Point& q = b.pslg.points[s.b];
    const bool outer = (p.r == 0.05 && q.r == 0.05) || (std::abs(p.z) == 0.05 && p.z == q.z);
    if (outer) s.boundary = 0;
  }
  b.region(0.005, 0.0, "core", core_size);
  b.region(0.015, 0.0, "coil");
  b.region(0.02, 0.0, "gap", 0.0, GapKind::annular);
  b.region(0.023, 0.0, "housing");
  b.region(0.04, 0.0, "air");
  b.pslg.source = "valve_like";
  return b.pslg;
}

/// Signed area of triangle t (positive when counter-clockwise) [m^2].
inline double signed_area(const Mesh& mesh, std::size_t t) {
  const Point& a = mesh.nodes[mesh.triangles[t][0]];
  const Point& b = mesh.nodes[mesh.triangles[t][1]];
  const Point& c = mesh.nodes[mesh.triangles[t][2]];
  return 0.5 * ((b.r - a.r) * (c.z - a.z) - (b.z - a.z) * (c.r - a.r));
}

/// Length of the edge between nodes i and j [m].
inline double edge_length(const Mesh& mesh, int i, int j) {
  return std::hypot(mesh.nodes[i].r - mesh.nodes[j].r, mesh.nodes[i].z - mesh.nodes[j].z);
}

/// Longest edge of triangle t [m].
inline double longest_edge(const Mesh& mesh, std::size_t t) {
  const auto& v = mesh.triangles[t];
  return std::max({edge_length(mesh, v[0], v[1]), edge_length(mesh, v[1], v[2]),
                   edge_length(mesh, v[2], v[0])});
}

}  // namespace rheomag::mesh::fixtures
