// Linear to quadratic triangles (see elevate.hpp).

#include "mesh/elevate.hpp"

#include <cstdint>
#include <unordered_map>

#include "mesh/edge_key.hpp"

namespace rheomag::mesh {

Mesh elevate_to_p2(const Mesh& linear) {
  if (linear.order == 2) return linear;
  Mesh quadratic = linear;
  quadratic.order = 2;
  quadratic.nodes.resize(static_cast<std::size_t>(linear.vertex_count));
  std::unordered_map<std::uint64_t, int> midpoint_of_edge;
  midpoint_of_edge.reserve(linear.triangles.size() * 2);
  auto midpoint = [&](int a, int b) {
    auto [it, inserted] =
        midpoint_of_edge.try_emplace(edge_key(a, b), static_cast<int>(quadratic.nodes.size()));
    if (inserted) {
      const Point& pa = linear.nodes[static_cast<std::size_t>(a)];
      const Point& pb = linear.nodes[static_cast<std::size_t>(b)];
      quadratic.nodes.push_back({0.5 * (pa.r + pb.r), 0.5 * (pa.z + pb.z)});
    }
    return it->second;
  };
  // Midpoints are numbered in order of first appearance: deterministic for a given mesh.
  for (auto& t : quadratic.triangles) {
    t[3] = midpoint(t[0], t[1]);
    t[4] = midpoint(t[1], t[2]);
    t[5] = midpoint(t[2], t[0]);
  }
  for (auto& e : quadratic.boundary_edges) e.nodes[2] = midpoint(e.nodes[0], e.nodes[1]);
  return quadratic;
}

}  // namespace rheomag::mesh
