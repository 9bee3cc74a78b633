#pragma once
// Conversion of checked region outlines to the mesher's PSLG.

#include <string>
#include <vector>

#include "case/region_outline.hpp"
#include "mesh/pslg.hpp"

namespace rheomag::cases {

/// Length below which two points of these outlines coincide: 1e-9 of the geometry's extent [m].
double outline_tolerance(const std::vector<RegionOutline>& regions);

/// Checks every outline (simple, closed, disjoint interiors) and builds the PSLG: coincident
/// points merged, edges split where another region's vertex lies on them, shared edges stored
/// once, one seed strictly inside each region (same order as `regions`). When `background` is
/// not empty a last region of that name is appended and made Pslg::default_region: it is the
/// space between the regions (the air), its seed lies outside every outline.
mesh::Pslg outlines_to_pslg(const std::vector<RegionOutline>& regions, const std::string& source,
                            const std::string& background);

}  // namespace rheomag::cases
