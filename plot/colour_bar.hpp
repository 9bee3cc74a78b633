#pragma once
// The colour bar of a banded colour map.

#include <cairo.h>

#include <string>

#include "plot/axes.hpp"
#include "plot/colour_map.hpp"

namespace rheomag::plot {

/// Draws the bins of `colours` as a vertical bar filling `area` (lowest bin at the bottom), tick
/// labels on its right and `label` above it.
void draw_colour_bar(cairo_t* cr, Rect area, const ColourMap& colours, const std::string& label);

}  // namespace rheomag::plot
