#pragma once
// Internal to rheomag_mesh: a PSLG inserted into a constrained Delaunay triangulation, and the
// flood fill that finds its enclosed areas (plain CGAL, no size field or quality measures).

#include "mesh/cdt.hpp"
#include "mesh/pslg_check.hpp"

namespace rheomag::mesh::detail {

/// Gives `label` to every still unlabelled face reachable from `start` without crossing a
/// constrained edge.
void flood_fill(const Cdt& cdt, Cdt::Face_handle start, int label);

/// Inserts the points and segments (segments longer than their max_length are cut into equal
/// pieces) and records each constrained edge's boundary marker and max_length in FaceInfo.
void insert_pslg(const PreparedPslg& prepared, Cdt& cdt);

}  // namespace rheomag::mesh::detail
