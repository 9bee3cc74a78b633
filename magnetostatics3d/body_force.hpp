#pragma once
// Magnetic force on a rigid body surrounded by air, from the Maxwell stress in the air.

#include <Eigen/Core>
#include <vector>

#include "magnetostatics3d/tet_mesh.hpp"

namespace rheomag::magnetostatics3d {

/// Force [N] on the body made of the regions with in_body[region] (per mesh region), for B per
/// tetrahedron: F = -integral T . grad g dV with the Maxwell stress of air
/// T = (B B^T - |B|^2 I / 2) / mu0 and g the piecewise linear function that is 1 at the body's
/// nodes and 0 at all others (virtual work of a rigid displacement of the body's nodes; equal to
/// the stress integrated over any surface in the air enclosing the body, since div T = 0 there).
/// grad g is nonzero only in the layer of tetrahedra touching the body from outside, which must
/// lie in regions with is_air[region]; throws std::logic_error otherwise.
Eigen::Vector3d body_force(const TetMesh& mesh, const std::vector<Eigen::Vector3d>& b,
                           const std::vector<bool>& in_body, const std::vector<bool>& is_air);

}  // namespace rheomag::magnetostatics3d
