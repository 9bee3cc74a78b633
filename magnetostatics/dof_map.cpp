#include "magnetostatics/dof_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace rheomag::magnetostatics {

DofMap build_dof_map(const mesh::Mesh& mesh, const cases::Problem& problem) {
  const std::size_t count = mesh.nodes.size();
  std::vector<bool> fixed(count, false);
  DofMap map;
  map.fixed_value.assign(count, 0.0);

  for (const mesh::BoundaryEdge& edge : mesh.boundary_edges) {
    if (edge.boundary < 0) continue;
    if (edge.boundary >= static_cast<int>(problem.boundaries.size())) {
      throw InputError("boundary marker " + std::to_string(edge.boundary) + " of a mesh edge has " +
                       "no boundary condition (" + std::to_string(problem.boundaries.size()) +
                       " defined)");
    }
    const cases::BoundaryCondition& bc = problem.boundaries[edge.boundary];
    if (bc.kind != cases::BoundaryKind::prescribed_a) continue;
    for (int node : edge.nodes) {
      if (node < 0) continue;
      fixed[node] = true;
      map.fixed_value[node] = bc.a_value;
    }
  }
  if (problem.symmetry == cases::Symmetry::axisymmetric) {
    double extent = 0.0;
    for (const mesh::Point& p : mesh.nodes)
      extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
    const double tolerance = 1e-9 * extent;
    for (std::size_t i = 0; i < count; ++i) {
      if (std::abs(mesh.nodes[i].r) <= tolerance) {
        fixed[i] = true;
        map.fixed_value[i] = 0.0;
      }
    }
  }
  map.dof_of_node.assign(count, -1);
  for (std::size_t i = 0; i < count; ++i) {
    if (fixed[i]) continue;
    map.dof_of_node[i] = static_cast<int>(map.node_of_dof.size());
    map.node_of_dof.push_back(static_cast<int>(i));
  }
  return map;
}

}  // namespace rheomag::magnetostatics
