#pragma once
// Internal to rheomag_mesh: a triangular lattice of points that starts the refinement close to
// its goal, so CGAL's bad-face queue stays short (about 5x faster on 1e5+ triangles).

#include <vector>

#include "mesh/cdt.hpp"
#include "mesh/size_field.hpp"

namespace rheomag::mesh::detail {

/// Points of an equilateral lattice of spacing 0.95 h_r inside every meshed region r of the
/// labelled coarse triangulation, left out where the size field asks for less than h_r (graded
/// zones, which CGAL refines) and within 0.45 of the spacing of a constrained edge.
/// `region_size[r]` is h_r, infinite for regions that are not meshed. Deterministic order,
/// spatially coherent.
std::vector<CgalPoint> lattice_points(const Cdt& coarse, const std::vector<double>& region_size,
                                      const SizeField& field);

}  // namespace rheomag::mesh::detail
