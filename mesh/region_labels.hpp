#pragma once
// Internal to rheomag_mesh: the coarse triangulation of the PSLG with a region on every face.

#include <vector>

#include "mesh/cdt.hpp"
#include "mesh/cdt_insert.hpp"
#include "mesh/pslg.hpp"
#include "mesh/pslg_check.hpp"

namespace rheomag::mesh::detail {

/// Area, perimeter and thickness of one region of the coarse triangulation [m^2, m, m].
struct RegionGeometry {
  double area = 0.0;
  double perimeter = 0.0;
  /// band_thickness(area, perimeter) (see quality.hpp).
  double thickness = 0.0;
};

/// Labels every face with its region: kOutside for faces connected to infinity, then the
/// area around each seed, then Pslg::default_region for the rest. Throws InputError for a seed
/// outside every closed boundary, two seeds in one area, or an area without region.
void label_regions(const Pslg& pslg, Cdt& cdt);

/// Area, perimeter and thickness of each region of a labelled triangulation.
std::vector<RegionGeometry> region_geometry(const Cdt& cdt, int region_count);

}  // namespace rheomag::mesh::detail
