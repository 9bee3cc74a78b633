#pragma once
// Tetrahedral mesh of a revolved body swept from its meridian triangle mesh (prism layers).

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

}  // namespace rheomag::magnetostatics3d
