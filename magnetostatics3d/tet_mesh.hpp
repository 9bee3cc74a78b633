#pragma once
// Tetrahedral mesh with its edges: the support of lowest-order Nedelec (edge) elements.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <vector>

namespace rheomag::magnetostatics3d {

/// Local edges of a tetrahedron as pairs of local vertices (the Whitney edge order).
inline constexpr std::array<std::array<int, 2>, 6> kTetEdges{
    {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

/// Boundary kinds of mesh faces, from the PLC facet markers.
enum class FaceKind {
  interior = 0,  ///< an internal material interface (no condition)
  outer = 1,     ///< far boundary: tangential A prescribed
  symmetry = 2,  ///< meridian symmetry plane: tangential A = 0 (B tangent to the plane)
};

/// Linear tetrahedra (x, y, z in metres) with region per tetrahedron, unique edges oriented from
/// the lower to the higher node index, and the boundary faces that carry a condition.
struct TetMesh {
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::array<int, 4>> tets;
  std::vector<int> region;                    ///< region index per tetrahedron
  std::vector<std::array<int, 2>> edges;      ///< node pairs, first < second
  std::vector<std::array<int, 6>> tet_edges;  ///< global edge of each local edge (kTetEdges)
  std::vector<std::array<int, 3>> faces;      ///< boundary faces with a condition
  std::vector<FaceKind> face_kind;            ///< parallel to faces

  /// Builds edges and tet_edges from tets (call once after filling nodes and tets).
  void build_edges();
  /// Signed volume of tetrahedron t [m^3] (positive for the orientation used here).
  double volume(int t) const;
  /// Gradients of the four barycentric coordinates of tetrahedron t [1/m].
  std::array<Eigen::Vector3d, 4> gradients(int t) const;
  /// Centroid of tetrahedron t.
  Eigen::Vector3d centroid(int t) const;
};

/// Orientation sign of local edge e of tetrahedron t: +1 when local (a -> b) runs from the lower
/// to the higher global node, else -1.
inline double edge_sign(const TetMesh& m, int t, int e) {
  const auto& v = m.tets[t];
  return v[kTetEdges[e][0]] < v[kTetEdges[e][1]] ? 1.0 : -1.0;
}

/// Curls of the six Whitney functions of tetrahedron t, signed to the global edge orientation:
/// curl w_e = 2 grad(lambda_a) x grad(lambda_b) (constant in the element).
std::array<Eigen::Vector3d, 6> edge_curls(const TetMesh& m, int t);

}  // namespace rheomag::magnetostatics3d
