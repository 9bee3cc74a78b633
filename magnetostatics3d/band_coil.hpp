#pragma once
// A coil wound around the z axis whose winding fills a band of constant width inside a rounded
// rectangle (e.g. the coil of TEAM problem 20): a non-azimuthal, discretely divergence-free
// source.

#include <Eigen/Core>

#include "magnetostatics3d/tet_mesh.hpp"

namespace rheomag::magnetostatics3d {

/// The winding occupies, for z0 <= z <= z1, the points of the rounded rectangle |x| <= half_x,
/// |y| <= half_y (corners rounded with corner_radius, centred on the z axis) within `width` of its
/// outline: the band between the outline and its inward offset [m]. `turns` turns.
struct BandCoil {
  double half_x = 0.0, half_y = 0.0, corner_radius = 0.0;
  double width = 0.0;
  double z0 = 0.0, z1 = 0.0;
  double turns = 1.0;
};

/// Distance from (x, y) inside the coil's outline to the outline (negative outside) [m].
double band_coil_depth(const BandCoil& coil, double x, double y);

/// Source field T = T_z e_z at 1 A with curl T = J, the winding's current density (turns /
/// (width x height), tangent to the outline, counter-clockwise about +z): T_z = J x (depth
/// clipped to [0, width]) for z0 <= z <= z1, 0 elsewhere. Its gradient has length 1 normal to
/// the outline, so |curl T| = J in the band, 0 in the hole and outside; T_z jumps only across
/// the planes z = z0, z1, where e_z is normal, so n x T is continuous and curl T = J exactly.
double band_coil_tz(const BandCoil& coil, const Eigen::Vector3d& p);

/// Edge loads f_e = integral T . curl w_e dV at 1 A (z_source_loads; flux linkage f . a).
/// Throws InputError unless the sizes are positive, the corner radius at most the half sizes and
/// the width below them.
Eigen::VectorXd band_coil_loads(const BandCoil& coil, const TetMesh& mesh);

}  // namespace rheomag::magnetostatics3d
