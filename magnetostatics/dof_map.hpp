#pragma once
// Degrees of freedom: one unknown A per mesh node, minus the nodes where A is prescribed.

#include <Eigen/Core>
#include <Eigen/SparseCore>
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

  /// Periodic and antiperiodic boundaries: the free values are reduction x (the reduced
  /// unknowns) + reduction_offset. Empty (0 x 0) when the model has none: reduced = free.
  Eigen::SparseMatrix<double> reduction;
  Eigen::VectorXd reduction_offset;  ///< per free dof (prescribed values reached via a pair)
  std::vector<int> free_of_reduced;  ///< the free dof each reduced unknown is
  bool antiperiodic = false;         ///< an antiperiodic pair is active (it excludes A = const)

  /// Number of free unknowns.
  int free_count() const { return static_cast<int>(node_of_dof.size()); }
  /// True when (anti)periodic pairs tie some free dofs to others.
  bool constrained() const { return reduction.rows() > 0; }
  /// Number of independent unknowns (free_count() unless constrained()).
  int reduced_count() const {
    return constrained() ? static_cast<int>(reduction.cols()) : free_count();
  }
  /// Reduced unknowns -> free dofs (identity unless constrained()).
  Eigen::VectorXd expand(const Eigen::VectorXd& reduced) const;
  /// Free-dof residual or load -> reduced (the transpose of expand's linear part).
  Eigen::VectorXd reduce(const Eigen::VectorXd& free) const;
};

/// Prescribes A = 0 on every node on the axis r = 0 (axisymmetric; |r| <= 1e-9 x mesh extent),
/// A = value on the nodes of mesh boundary edges whose marker is a `prescribed_a` condition and
/// at the nodes of prescribed point conditions; the axis wins where both apply. A planar problem
/// with none of these and no mixed boundary with c0 > 0 has A only up to a constant: its first
/// node is pinned to A = 0 (gauge_node), which changes no flux density (an exact gauge fix; a
/// small regularisation would perturb B). Periodic and antiperiodic pairs tie the slave nodes to
/// the master edge (periodic.hpp, `reduction`); an antiperiodic pair determines A by itself, and
/// the gauge node is never a slave. Throws InputError for a marker outside
/// Problem::boundaries or a point condition with no mesh node.
DofMap build_dof_map(const mesh::Mesh& mesh, const cases::Problem& problem);

/// The mesh node at geometry point `point` of the problem (within 1e-9 x mesh extent);
/// InputError if there is none.
int mesh_node_at(const mesh::Mesh& mesh, const cases::Problem& problem, int point);

}  // namespace rheomag::magnetostatics
