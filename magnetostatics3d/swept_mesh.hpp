#pragma once
// Tetrahedral mesh of a revolved body swept from its meridian triangle mesh (prism layers).

#include <Eigen/Core>
#include <vector>

#include "magnetostatics3d/revolve.hpp"
#include "magnetostatics3d/tet_mesh.hpp"
#include "mesh/mesh.hpp"

namespace rheomag::magnetostatics3d {

/// Angles of a revolution over [0, span] whose steps are `fine` [rad] at every angle of `walls`
/// and grow by the factor `growth` per step away from them, up to `coarse` [rad]: fine where a
/// feature breaks the symmetry, coarse where the field is nearly axisymmetric. Every wall is
/// among the angles.
Revolution graded_revolution(double span, const std::vector<double>& walls, double fine,
                             double coarse, double growth);

/// Sweeps the linear triangle mesh `meridian` (of a closed axisymmetric problem: its regions
/// are the problem's, its marked boundary edges the outer boundary) about z through the angles
/// of `revolution`: every triangle x angular interval is a prism split into three tetrahedra,
/// the diagonal of each quadrilateral side running from the lower-numbered meridian node at the
/// lower angle to the other node at the higher angle, so neighbouring prisms share their faces.
/// Nodes on the axis are one node (the prisms there become pyramids or tetrahedra). Faces swept
/// from marked boundary edges are FaceKind::outer, the end planes of a wedge FaceKind::symmetry.
/// Elements are long in phi where the steps are coarse: the field's azimuthal variation is
/// resolved by the angles, its meridian variation by the triangles.
TetMesh sweep_mesh(const mesh::Mesh& meridian, const Revolution& revolution);

/// Radial factor c_k per angle of `revolution` that gives the facetted rings their true area:
/// the polygon through the nodes at radius r c_k on the angles phi_k encloses
/// sum_k r^2 c_k c_(k+1) sin(d_k) / 2 with d_k = phi_(k+1) - phi_k, which is the sector's
/// r^2 d_k / 2 when c_k c_(k+1) = q_k = d_k / sin(d_k); c_k = (q_(k-1) q_k)^(1/4) (q of the one
/// neighbouring step at the ends of a partial revolution) meets it to second order in the change
/// of step. Without it the chords shrink every axial flux path by sin(d) / d (-1.1 % at 15
/// degrees), which the flux linkage of a saturated core follows.
std::vector<double> ring_area_factors(const Revolution& revolution);

/// Scales x and y of every node by the factor of its angle (ring_area_factors), the angle read
/// from `swept` (the same nodes as swept, before features moved any).
void restore_ring_areas(std::vector<Eigen::Vector3d>& nodes,
                        const std::vector<Eigen::Vector3d>& swept, const Revolution& revolution);

}  // namespace rheomag::magnetostatics3d
