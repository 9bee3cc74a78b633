#pragma once
// Internal to rheomag_mesh: which region a point lies in, found in a triangulation of the PSLG
// refined for shape only, so that locating a point never walks a fan of slivers.

#include <vector>

#include "mesh/cdt.hpp"
#include "mesh/pslg.hpp"

namespace rheomag::mesh::detail {

/// The regions of a PSLG by point. Locating in the PSLG's own constrained triangulation walks
/// through every sliver between the query and the last point found, and a boundary of many
/// short pieces (a finely cut segment, a finely divided arc) fans that triangulation into
/// thousands of slivers: a copy refined to angles of about 20 degrees (when it has more than
/// 2000 vertices), and walks started from a face found near p on a uniform grid, keep every walk
/// short.
class RegionLocator {
 public:
  /// A copy of `outline` (the PSLG's triangulation) refined for shape and labelled anew.
  RegionLocator(const Cdt& outline, const Pslg& pslg);

  /// Region containing p (an index into Pslg::regions), or kOutside.
  int region_at(const CgalPoint& p) const;

 private:
  Cdt cdt_;
  // A face at the centre of each cell of a uniform grid over the bounding box, row by row.
  double r0_ = 0.0, z0_ = 0.0, cell_ = 1.0;
  int columns_ = 1, rows_ = 1;
  std::vector<Cdt::Face_handle> start_;
  // The last query's cell and face: a query in the same cell starts from there.
  mutable std::size_t last_cell_ = 0;
  mutable Cdt::Face_handle last_face_;
};

}  // namespace rheomag::mesh::detail
