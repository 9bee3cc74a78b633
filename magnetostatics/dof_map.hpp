#pragma once
// Degrees of freedom: one unknown A per mesh node, minus the nodes where A is prescribed.

#include <vector>

#include "case/problem.hpp"
#include "mesh/mesh.hpp"

namespace rheomag::magnetostatics {

/// Numbering of the free nodal values of A and the prescribed (Dirichlet) values of the others.
struct DofMap {
  std::vector<int> dof_of_node;     ///< free dof index per node, -1 where A is prescribed
  std::vector<int> node_of_dof;     ///< inverse map
  std::vector<double> fixed_value;  ///< per node: the prescribed A [Wb/m] (0 for free nodes)
  /// Node pinned to A = 0 to fix the gauge of a planar problem whose A is otherwise determined
  /// only up to a constant (no prescribed A, no mixed boundary with c0 > 0); -1 if none.
  int gauge_node = -1;

  /// Number of free unknowns.
  int free_count() const { return static_cast<int>(node_of_dof.size()); }
};

/// Prescribes A = 0 on every node on the axis r = 0 (axisymmetric; |r| <= 1e-9 x mesh extent),
/// A = value on the nodes of mesh boundary edges whose marker is a `prescribed_a` condition and
/// at the nodes of prescribed point conditions; the axis wins where both apply. A planar problem
/// with none of these and no mixed boundary with c0 > 0 has A only up to a constant: its first
/// node is pinned to A = 0 (gauge_node), which changes no flux density (an exact gauge fix; a
/// small regularisation would perturb B). Throws InputError for a marker outside
/// Problem::boundaries or a point condition with no mesh node.
DofMap build_dof_map(const mesh::Mesh& mesh, const cases::Problem& problem);

/// The mesh node at geometry point `point` of the problem (within 1e-9 x mesh extent);
/// InputError if there is none.
int mesh_node_at(const mesh::Mesh& mesh, const cases::Problem& problem, int point);

}  // namespace rheomag::magnetostatics
