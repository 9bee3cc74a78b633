#pragma once
// Internal to rheomag_mesh: a PSLG inserted into a constrained Delaunay triangulation, and the
// flood fill that finds its enclosed areas (plain CGAL, no size field or quality measures).

#include "mesh/cdt.hpp"
#include "mesh/pslg_check.hpp"

namespace rheomag::mesh::detail {

/// Gives `label` to every still unlabelled face reachable from `start` without crossing a
/// constrained edge.
void flood_fill(const Cdt& cdt, Cdt::Face_handle start, int label);

/// What insert_pslg does with a segment longer than its max_length.
enum class SegmentPieces {
  cut,    ///< cut into equal pieces no longer than max_length (the mesh's boundary nodes)
  whole,  ///< inserted whole (a triangulation only to locate regions and size sources in)
};

/// Inserts the points and segments and records each constrained edge's boundary marker and
/// max_length in FaceInfo.
void insert_pslg(const PreparedPslg& prepared, Cdt& cdt, SegmentPieces pieces = SegmentPieces::cut);

}  // namespace rheomag::mesh::detail
