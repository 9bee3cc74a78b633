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

  /// Number of free unknowns.
  int free_count() const { return static_cast<int>(node_of_dof.size()); }
};

/// Prescribes A = 0 on every node on the axis r = 0 (axisymmetric; |r| <= 1e-9 x mesh extent)
/// and A = value on the nodes of mesh boundary edges whose marker is a `prescribed_a` condition;
/// the axis wins where both apply. Throws InputError for a marker outside Problem::boundaries.
DofMap build_dof_map(const mesh::Mesh& mesh, const cases::Problem& problem);

}  // namespace rheomag::magnetostatics
