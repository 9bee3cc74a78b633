#pragma once
// Azimuthal coil currents of a revolved problem as discretely divergence-free edge loads.

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "case/problem.hpp"
#include "magnetostatics3d/tet_mesh.hpp"
#include "mesh/mesh.hpp"

namespace rheomag::magnetostatics3d {

/// The z component T_z(x) of a source field T = T_z e_z at unit current [1/m^2 x m = turns/m].
using SourceTz = std::function<double(const Eigen::Vector3d&)>;

/// Edge loads f_e = integral T_z e_z . curl w_e dV of a source T = T_z e_z (curl T = J) that
/// vanishes outside z_min <= z <= z_max. T_z is evaluated at `nodes` (one per mesh node) with a
/// degree-2 rule, on 64 sub-tetrahedra when `jumps(z_lo, z_hi)` says T_z jumps inside a
/// tetrahedron spanning z_lo..z_hi. n x T is continuous when T_z jumps only across planes
/// z = const; the load is then the transpose curl of something and orthogonal to every discrete
/// gradient (a discretely divergence-free source).
Eigen::VectorXd z_source_loads(const TetMesh& mesh, const std::vector<Eigen::Vector3d>& nodes,
                               const SourceTz& tz, double z_min, double z_max,
                               const std::function<bool(double, double)>& jumps);

/// T_z(r, z) of every circuit at 1 A, the source field circuit_loads integrates (see there).
std::vector<std::function<double(double, double)>> circuit_source_tz(const cases::Problem& closed,
                                                                     const mesh::Mesh& meridian);

/// Edge loads f_ce = integral T_c . curl w_e dV of every circuit c at 1 A, where T_c is a source
/// field with curl T_c = J_c, the coil current density (turns / meridian area of each coil
/// region, azimuthal). T_c = T_z(r, z) e_z with T_z(r, z) = sum over the circuit's coil regions
/// of (N / S) x (length of the part of the horizontal line through (r, z) inside the region at
/// radius > r): -dT_z/dr = J_phi and n x T is continuous, so curl T = J exactly. Because the load
/// is the transpose curl of something, it is orthogonal to every discrete gradient: the coil
/// source is discretely divergence-free whatever the quadrature. The coil regions are taken from
/// `meridian`, a linear triangle mesh of the closed problem (its triangles tile each region
/// exactly); integrals over tetrahedra use a degree-2 rule, on 64 sub-tetrahedra where T_z jumps
/// (across the planes of horizontal coil edges). Also the flux linkage is lambda_c = f_c . a.
/// `source_nodes` (one per mesh node) are the positions at which T is evaluated: the mesh's own
/// nodes, or the undeformed ones when the part of the mesh holding the coils was moved rigidly.
std::vector<Eigen::VectorXd> circuit_loads(const cases::Problem& closed, const mesh::Mesh& meridian,
                                           const TetMesh& mesh,
                                           const std::vector<Eigen::Vector3d>& source_nodes);

}  // namespace rheomag::magnetostatics3d
