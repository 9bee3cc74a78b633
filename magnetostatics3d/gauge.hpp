#pragma once
// Tree-cotree gauge of lowest-order edge elements.

#include <Eigen/Core>
#include <vector>

#include "magnetostatics3d/tet_mesh.hpp"

namespace rheomag::magnetostatics3d {

/// Unknowns of the gauged edge-element system: fixed edges (tangential A prescribed on outer and
/// symmetry faces) and tree edges (A = 0) are eliminated, the cotree edges are the unknowns.
struct EdgeDofs {
  std::vector<int> dof_of_edge;  ///< unknown index per edge, -1 for fixed and tree edges
  std::vector<int> edge_of_dof;  ///< edge per unknown
  std::vector<bool> fixed;       ///< per edge: on a face with a condition
  int tree_edges = 0;            ///< edges removed by the gauge
  int free_count() const { return static_cast<int>(edge_of_dof.size()); }
};

/// Marks the edges of the mesh's condition faces as fixed and removes a spanning tree of the
/// remaining edges, grown from all fixed-edge nodes taken as one node. The stiffness matrix on
/// the cotree edges is then positive definite when the condition faces form one connected
/// surface (the discrete gradients that vanish there are exactly what the tree removes).
/// Throws InputError if the mesh has no condition face (A would not be determined).
EdgeDofs tree_cotree_dofs(const TetMesh& mesh);

/// The ungauged unknowns: every edge off the condition faces (no tree removed), for solvers of
/// the singular curl-curl system (AMS). Throws InputError as tree_cotree_dofs.
EdgeDofs free_edge_dofs(const TetMesh& mesh);

/// The unknowns (cotree values) of the gauged field with the same curl as the edge values `a`
/// (one per edge, zero tangential A on the fixed edges): a minus the discrete gradient of the
/// potential that is zero on the fixed edges' nodes and integrates `a` along the tree, so that
/// every tree edge becomes 0. A field given on all edges (e.g. interpolated) becomes a start of
/// EdgeSolver's Newton iteration without changing its B.
Eigen::VectorXd cotree_values(const TetMesh& mesh, const EdgeDofs& dofs, const Eigen::VectorXd& a);

}  // namespace rheomag::magnetostatics3d
