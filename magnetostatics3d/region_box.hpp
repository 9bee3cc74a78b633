#pragma once
// Meridian bounding boxes of the regions of a revolved problem.

#include <cmath>
#include <vector>

#include "mesh/mesh.hpp"

namespace rheomag::magnetostatics3d {

/// Bounding box of one region in the meridian (r, z) plane [m].
struct RegionBox {
  double r0 = INFINITY, r1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
  /// True when the region has no triangle.
  bool empty() const { return r1 < r0; }
};

/// Box of each of `regions` regions from a triangle mesh of the meridian plane.
std::vector<RegionBox> region_boxes(const mesh::Mesh& meridian, std::size_t regions);

}  // namespace rheomag::magnetostatics3d
