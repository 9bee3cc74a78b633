#include "magnetostatics/dof_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "magnetostatics/periodic.hpp"

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
      map.fixed_value[node] = bc.a_at(mesh.nodes[node]);
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
  const PeriodicConstraints periodic = periodic_constraints(mesh, problem, fixed);
  // Planar A is determined up to a constant. (Axisymmetric A_phi up to C/r, which the discrete
  // space does not contain: an axisymmetric model off the axis without any condition is refused
  // by the solver instead.) An antiperiodic pair excludes the constant.
  const bool determined =
      problem.symmetry == cases::Symmetry::axisymmetric || periodic.antiperiodic ||
      std::find(fixed.begin(), fixed.end(), true) != fixed.end() ||
      std::any_of(mesh.boundary_edges.begin(), mesh.boundary_edges.end(),
                  [&](const mesh::BoundaryEdge& e) {
                    return e.boundary >= 0 &&
                           problem.boundaries[e.boundary].kind == cases::BoundaryKind::mixed &&
                           problem.boundaries[e.boundary].c0 > 0.0;
                  });
  if (!determined) {
    for (std::size_t i = 0; i < count && map.gauge_node < 0; ++i)
      if (!periodic.slave[i]) map.gauge_node = static_cast<int>(i);
    if (map.gauge_node >= 0) fixed[map.gauge_node] = true;
  }
  map.antiperiodic = periodic.antiperiodic;
  map.dof_of_node.assign(count, -1);
  for (std::size_t i = 0; i < count; ++i) {
    if (fixed[i]) continue;
    map.dof_of_node[i] = static_cast<int>(map.node_of_dof.size());
    map.node_of_dof.push_back(static_cast<int>(i));
  }
  if (!periodic.any()) return map;
  // Free dofs -> reduced unknowns: the non-slave free dofs; slaves are combinations of them and
  // of prescribed values.
  const int free = map.free_count();
  std::vector<int> reduced_of_free(free, -1);
  for (int d = 0; d < free; ++d) {
    if (periodic.slave[map.node_of_dof[d]]) continue;
    reduced_of_free[d] = static_cast<int>(map.free_of_reduced.size());
    map.free_of_reduced.push_back(d);
  }
  std::vector<Eigen::Triplet<double>> entries;
  map.reduction_offset = Eigen::VectorXd::Zero(free);
  for (int d = 0; d < free; ++d) {
    const int node = map.node_of_dof[d];
    if (!periodic.slave[node]) {
      entries.emplace_back(d, reduced_of_free[d], 1.0);
      continue;
    }
    for (const NodeTerm& term : periodic.terms[node]) {
      const int master = map.dof_of_node[term.node];
      if (master < 0)
        map.reduction_offset[d] += term.weight * map.fixed_value[term.node];
      else
        entries.emplace_back(d, reduced_of_free[master], term.weight);
    }
  }
  map.reduction.resize(free, static_cast<Eigen::Index>(map.free_of_reduced.size()));
  map.reduction.setFromTriplets(entries.begin(), entries.end());
  return map;
}

Eigen::VectorXd DofMap::expand(const Eigen::VectorXd& reduced) const {
  if (!constrained()) return reduced;
  return reduction * reduced + reduction_offset;
}

Eigen::VectorXd DofMap::reduce(const Eigen::VectorXd& free) const {
  if (!constrained()) return free;
  return reduction.transpose() * free;
}

}  // namespace rheomag::magnetostatics
