#pragma once
// Polygon-level checks of region outlines with clear messages (before the mesher sees a PSLG):
// simple closed polygons, disjoint interiors, and a point strictly inside each region.

#include <vector>

#include "case/region_outline.hpp"

namespace rheomag::cases {

/// Where a point lies relative to a polygon.
enum class Location { outside, boundary, inside };

/// Locates `p` relative to `polygon`; points within `tolerance` of an edge are on the boundary.
Location locate(const mesh::Point& p, const std::vector<mesh::Point>& polygon, double tolerance);

/// Throws InputError if the outline has fewer than 3 distinct vertices, zero area or crosses or
/// touches itself. `tolerance` is the length below which points coincide [m].
void check_simple_polygon(const RegionOutline& region, double tolerance);

/// Throws InputError if the interiors of the two outlines overlap (sharing edges is fine).
void check_disjoint(const RegionOutline& a, const RegionOutline& b, double tolerance);

/// A point strictly inside a simple polygon, as far from its edges as a slab search finds.
mesh::Point interior_point(const std::vector<mesh::Point>& polygon);

/// Signed area of a polygon (positive counter-clockwise) [m^2].
double signed_area(const std::vector<mesh::Point>& polygon);

}  // namespace rheomag::cases
