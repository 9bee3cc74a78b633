#pragma once
// Piecewise linear complex: the input of the tetrahedral mesher.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "magnetostatics3d/tet_mesh.hpp"

namespace rheomag::magnetostatics3d {

/// One planar facet: polygons given by point indices (a 2-point polygon is a constrained
/// segment inside the facet), and the condition its mesh faces carry.
struct PlcFacet {
  std::vector<std::vector<int>> polygons;
  FaceKind kind = FaceKind::interior;
};

/// A region seed: the connected part of the domain containing `point` gets region `region`,
/// with tetrahedra of at most `max_volume` [m^3] (0 = no limit).
struct PlcRegion {
  Eigen::Vector3d point;
  int region = -1;
  double max_volume = 0.0;
};

/// Points, facets, region seeds and hole seeds of a 3D domain [m].
struct Plc {
  std::vector<Eigen::Vector3d> points;
  std::vector<PlcFacet> facets;
  std::vector<PlcRegion> regions;
  std::vector<Eigen::Vector3d> holes;  ///< points inside regions that are not meshed
  int default_region = -1;             ///< region of tetrahedra reached by no seed
  std::string source;                  ///< name used in error messages
};

/// Quality and size settings of the tetrahedral mesher.
struct TetMeshOptions {
  double radius_edge_ratio = 1.5;  ///< largest circumradius / shortest edge (TetGen -q)
  double min_dihedral = 12.0;      ///< smallest dihedral angle [degree] (TetGen -q)
};

/// Tetrahedralises `plc` with TetGen (constrained Delaunay, quality refinement, region volume
/// limits), in a child process because TetGen 1.5.0 crashes when it stops on bad input. Throws
/// InputError naming plc.source when TetGen rejects the input (e.g. self-intersecting facets) or
/// a tetrahedron is left without a region.
TetMesh tetrahedralize(const Plc& plc, const TetMeshOptions& options = {});

}  // namespace rheomag::magnetostatics3d
