#include "magnetostatics3d/region_box.hpp"

#include <algorithm>

namespace rheomag::magnetostatics3d {

std::vector<RegionBox> region_boxes(const mesh::Mesh& meridian, std::size_t regions) {
  std::vector<RegionBox> box(regions);
  for (std::size_t e = 0; e < meridian.triangles.size(); ++e) {
    RegionBox& b = box[meridian.region[e]];
    for (int k = 0; k < 3; ++k) {
      const mesh::Point& p = meridian.nodes[meridian.triangles[e][k]];
      b.r0 = std::min(b.r0, p.r);
      b.r1 = std::max(b.r1, p.r);
      b.z0 = std::min(b.z0, p.z);
      b.z1 = std::max(b.z1, p.z);
    }
  }
  return box;
}

}  // namespace rheomag::magnetostatics3d
