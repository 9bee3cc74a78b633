#pragma once
// Internal to rheomag_mesh: the target element edge length at any point of the domain.

#include <vector>

#include "mesh/cdt.hpp"
#include "mesh/pslg.hpp"
#include "mesh/region_locator.hpp"

namespace rheomag::mesh::detail {

/// h(x) = min(h_region(x), min over finer segments s of h_s + grading * distance(x, s)), where
/// h_region is the target of the region containing x (a RegionLocator) and h_s the smallest target
/// on either side of constrained edge s (or its max_length). The second term grades the mesh away
/// from small regions and short edges.
class SizeField {
 public:
  /// `region_size[r]` is the target edge length of region r [m]; `outline` is the labelled
  /// triangulation of `pslg` with its segments whole (read here only).
  SizeField(const Cdt& outline, const Pslg& pslg, std::vector<double> region_size, double grading);

  /// Target edge length at p [m].
  double at(const CgalPoint& p) const;

  /// Region containing p (a face label of the coarse triangulation).
  int region_at(const CgalPoint& p) const;

 private:
  struct Source {
    CgalPoint a, b;
    double size;
  };
  void add_to_grid(int source, double reach);

  RegionLocator regions_;
  std::vector<double> region_size_;
  double grading_;
  std::vector<Source> sources_;
  // Uniform grid of buckets over the bounding box: the sources that can bind in each cell.
  double r0_ = 0.0, z0_ = 0.0, cell_ = 1.0;
  int columns_ = 0, rows_ = 0;
  std::vector<std::vector<int>> buckets_;
};

}  // namespace rheomag::mesh::detail
