#pragma once
// A start for the 3D Newton iteration: the axisymmetric 2D solution of the same case, revolved
// onto the edges of the 3D mesh.

#include <Eigen/Core>

#include "case/problem.hpp"
#include "magnetostatics3d/tet_mesh.hpp"
#include "mesh/mesh.hpp"

namespace rheomag::magnetostatics3d {

/// Line integral of A = A_phi(r, z) e_phi along every edge of `mesh` (two-point Gauss rule on
/// the straight edge), A_phi [Wb/m] interpolated from the nodal 2D field `a_phi` on `meridian`
/// (its triangle containing each Gauss point, or the nearest one). Edges in a meridian plane get
/// 0 (e_phi is normal to them), so do edges on the axis.
Eigen::VectorXd revolved_edge_values(const TetMesh& mesh, const mesh::Mesh& meridian,
                                     const Eigen::VectorXd& a_phi);

/// The 2D solution of `closed` (axisymmetric, with its outer boundary, at its circuit currents)
/// on the linear triangle mesh `meridian` (the one the 3D mesh was made from, so that both
/// resolve the same corners alike) revolved onto the edges of `mesh` (revolved_edge_values).
/// Empty when the 2D Newton iteration does not converge (the 3D solve then starts from A = 0).
Eigen::VectorXd revolved_2d_solution(const cases::Problem& closed, const mesh::Mesh& meridian,
                                     const TetMesh& mesh);

}  // namespace rheomag::magnetostatics3d
