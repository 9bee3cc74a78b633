#include "magnetostatics/dof_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace rheomag::magnetostatics {
namespace {

double mesh_extent(const mesh::Mesh& mesh) {
  double extent = 0.0;
  for (const mesh::Point& p : mesh.nodes) extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
  return extent;
}

}  // namespace

int mesh_node_at(const mesh::Mesh& mesh, const cases::Problem& problem, int point) {
  const auto& points = problem.geometry.points;
  if (point < 0 || point >= static_cast<int>(points.size()))
    throw InputError(problem.geometry.source + ": point condition at point " +
                     std::to_string(point) + ", which does not exist");
  const mesh::Point p = points[point];
  int best = -1;
  double best_distance = 0.0;
  for (int i = 0; i < static_cast<int>(mesh.nodes.size()); ++i) {
    const double d = std::hypot(mesh.nodes[i].r - p.r, mesh.nodes[i].z - p.z);
    if (best < 0 || d < best_distance) best = i, best_distance = d;
  }
  if (best < 0 || best_distance > 1e-9 * mesh_extent(mesh))
    throw InputError(problem.geometry.source + ": point " + std::to_string(point) +
                     " of a point condition is not a mesh node (outside the meshed regions?)");
  return best;
}

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
  for (const cases::PointCondition& condition : problem.point_conditions) {
    if (!condition.prescribed) continue;
    const int node = mesh_node_at(mesh, problem, condition.point);
    fixed[node] = true;
    map.fixed_value[node] = condition.a_value;
  }
  if (problem.symmetry == cases::Symmetry::axisymmetric) {
    const double tolerance = 1e-9 * mesh_extent(mesh);
    for (std::size_t i = 0; i < count; ++i) {
      if (std::abs(mesh.nodes[i].r) <= tolerance) {
        fixed[i] = true;
        map.fixed_value[i] = 0.0;
      }
    }
  }
  // Planar A is determined up to a constant. (Axisymmetric A_phi up to C/r, which the discrete
  // space does not contain: an axisymmetric model off the axis without any condition is refused
  // by the solver instead.)
  const bool determined =
      problem.symmetry == cases::Symmetry::axisymmetric ||
      std::find(fixed.begin(), fixed.end(), true) != fixed.end() ||
      std::any_of(mesh.boundary_edges.begin(), mesh.boundary_edges.end(),
                  [&](const mesh::BoundaryEdge& e) {
                    return e.boundary >= 0 &&
                           problem.boundaries[e.boundary].kind == cases::BoundaryKind::mixed &&
                           problem.boundaries[e.boundary].c0 > 0.0;
                  });
  if (!determined && count > 0) {
    map.gauge_node = 0;
    fixed[0] = true;
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
