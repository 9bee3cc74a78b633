#pragma once
// Fields on flat triangles: filled by a banded colour map, and their contour lines.

#include <cairo.h>

#include <array>
#include <vector>

#include "plot/axes.hpp"
#include "plot/colour_map.hpp"

namespace rheomag::plot {

/// Flat triangles over points in data units.
struct TriangleMesh {
  std::vector<std::array<double, 2>> points;
  std::vector<std::array<int, 3>> triangles;
};

/// Fills every triangle of `mesh` in the colour of its value (`values`, one per triangle), one
/// path per colour bin, without anti-aliasing and outlined in its own colour, so that
/// neighbours show no seams.
void fill_triangles(cairo_t* cr, const Axes& axes, const TriangleMesh& mesh,
                    const std::vector<double>& values, const ColourMap& colours);

/// A straight piece of a contour line, in data units.
struct ContourSegment {
  std::array<double, 2> a, b;
  int level = 0;  ///< index into the levels
};

/// `count` levels at the centres of `count` equal parts of [low, high].
std::vector<double> centred_levels(double low, double high, int count);

/// The contour lines of the field that is linear on each triangle of `mesh` with the given
/// values at its points (`node_values`, one per point), at each of `levels`: in each triangle
/// the straight segment between the two edges the level crosses (vertices at or above a level
/// count as above it).
std::vector<ContourSegment> contour_segments(const TriangleMesh& mesh,
                                             const std::vector<double>& node_values,
                                             const std::vector<double>& levels);

/// Strokes `segments` in `colour` with line width `width` (pixels).
void draw_segments(cairo_t* cr, const Axes& axes, const std::vector<ContourSegment>& segments,
                   Rgb colour, double width);

}  // namespace rheomag::plot
