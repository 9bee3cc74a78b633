#pragma once
// Tetrahedral meshes of box-shaped geometries: a graded tensor-product grid of hexahedra, each
// split into six tetrahedra, with regions given by boxes.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <vector>

#include "magnetostatics3d/tet_mesh.hpp"

namespace rheomag::magnetostatics3d {

/// One stretch of a grid axis: from the previous coordinate to `end` [m], steps growing
/// geometrically from `first_step` to `last_step` (their number rounded up).
struct AxisSpan {
  double end = 0.0;
  double first_step = 0.0;
  double last_step = 0.0;
};

/// Grid coordinates from `start` through the spans (each span's end is a grid line). Throws
/// InputError unless the ends increase and the steps are positive.
std::vector<double> graded_axis(double start, const std::vector<AxisSpan>& spans);

/// A region made of one axis-aligned box; later boxes win where they overlap.
struct RegionBox3d {
  Eigen::AlignedBox3d box;
  int region = 0;
};

/// A box-shaped domain: grid lines per axis (the box faces of the regions should be among
/// them), region boxes, the region of the rest, and the condition of each side of the domain in
/// the order -x, +x, -y, +y, -z, +z (interior = none).
struct GridSpec {
  std::array<std::vector<double>, 3> lines;
  std::vector<RegionBox3d> boxes;
  int background_region = 0;
  std::array<FaceKind, 6> sides{FaceKind::outer, FaceKind::outer, FaceKind::outer,
                                FaceKind::outer, FaceKind::outer, FaceKind::outer};
};

/// Hexahedra of the grid, each split into six tetrahedra around its main diagonal (the same
/// split in every cell, so neighbours share faces: a conforming mesh); a tetrahedron's region is
/// that of the box holding its cell's centre. Boundary faces on a side with a condition are
/// recorded. Throws InputError unless every axis has >= 2 increasing lines.
TetMesh grid_mesh(const GridSpec& spec);

}  // namespace rheomag::magnetostatics3d
