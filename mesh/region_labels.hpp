#pragma once
// Internal to rheomag_mesh: the coarse triangulation of the PSLG with a region on every face.

#include <vector>

#include "mesh/cdt.hpp"
#include "mesh/pslg.hpp"
#include "mesh/pslg_check.hpp"

namespace rheomag::mesh::detail {

/// Area, perimeter and thickness of one region of the coarse triangulation [m^2, m, m].
struct RegionGeometry {
  double area = 0.0;
  double perimeter = 0.0;
  /// Thickness t of a thin band: the smaller root of t^2 - (P/2) t + A = 0, i.e. the short side
  /// of the rectangle with the region's area A and perimeter P (exact for rectangles and for
  /// bands of constant thickness; 4A/P if there is no real root, e.g. the diameter of a disc).
  double thickness = 0.0;
};

/// Inserts the points and segments (segments longer than their max_length are cut into equal
/// pieces) and records each constrained edge's boundary marker and max_length in FaceInfo.
void insert_pslg(const PreparedPslg& prepared, Cdt& cdt);

/// Labels every face with its region: kOutside for faces connected to infinity, then the
/// area around each seed, then Pslg::default_region for the rest. Throws InputError for a seed
/// outside every closed boundary, two seeds in one area, or an area without region.
void label_regions(const Pslg& pslg, Cdt& cdt);

/// Area, perimeter and thickness of each region of a labelled triangulation.
std::vector<RegionGeometry> region_geometry(const Cdt& cdt, int region_count);

}  // namespace rheomag::mesh::detail
