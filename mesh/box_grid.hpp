#pragma once
// Which of many boxes may touch a given box: a uniform grid of cells over their extent, so that
// the geometry checks of a case with 10^5 regions (points on edges, overlapping regions, seeds on
// segments) cost about the number of neighbours, not the number of pairs.

#include <cstddef>
#include <vector>

namespace rheomag::mesh {

/// An axis-aligned box in the (r, z) plane [m].
struct Box2 {
  double r_lo = 0.0, z_lo = 0.0, r_hi = 0.0, z_hi = 0.0;
};

/// Boxes filed in a uniform grid (about one box per cell); boxes spanning many cells are kept
/// aside and offered to every query.
class BoxGrid {
 public:
  /// Files `boxes` (indexed by position). Non-finite boxes are offered to every query.
  explicit BoxGrid(const std::vector<Box2>& boxes);

  /// Indices, ascending and each once, of the boxes that may overlap `query` (every box that
  /// does, closed intervals; some that do not).
  std::vector<int> candidates(const Box2& query) const;

 private:
  std::vector<Box2> boxes_;
  double r0_ = 0.0, z0_ = 0.0, cell_r_ = 1.0, cell_z_ = 1.0;
  int columns_ = 1, rows_ = 1;
  std::vector<std::size_t> start_;  ///< cell c's boxes are filed_[start_[c] .. start_[c + 1])
  std::vector<int> filed_;
  std::vector<int> everywhere_;  ///< boxes spanning many cells
};

}  // namespace rheomag::mesh
