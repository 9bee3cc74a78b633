#pragma once
// The discrete gradient of lowest-order edge elements: nodal values to edge line integrals.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "magnetostatics3d/tet_mesh.hpp"

namespace rheomag::magnetostatics3d {

/// Edge x node incidence G: G(e, first node) = -1, G(e, second node) = +1 (edges run from the
/// lower to the higher node), so that G phi are the Whitney edge values of grad phi for nodal
/// values phi, and curl(G phi) = 0 in every tetrahedron.
Eigen::SparseMatrix<double, Eigen::RowMajor, int> discrete_gradient(const TetMesh& mesh);

/// |G^T f| / |f| for edge values f (0 for f = 0): how far a load is from discretely
/// divergence-free, which the singular (ungauged) curl-curl system needs to be consistent.
double relative_divergence(const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& gradient,
                           const Eigen::VectorXd& f);

}  // namespace rheomag::magnetostatics3d
