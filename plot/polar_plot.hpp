#pragma once
// Polar plots: closed curves of a positive quantity against an angle.

#include <string>
#include <vector>

#include "plot/axes.hpp"
#include "plot/colour_map.hpp"
#include "plot/figure.hpp"

namespace rheomag::plot {

/// One closed curve: radius[i] (>= 0) at angle[i] [rad, counter-clockwise from the right].
struct PolarSeries {
  std::string name;
  std::vector<double> angle, radius;
  Rgb colour;
};

/// What a polar plot shows.
struct PolarPlot {
  std::string title;
  std::string unit;  ///< of the radius, written on the radial ticks' axis ("|B| [T]")
  std::vector<PolarSeries> series;
};

/// Draws `plot` in `area`: radial rings at nice values from 0, spokes every 30 degrees with their
/// angle, each series as a closed curve with a dot per point, and a legend.
void draw_polar_plot(cairo_t* cr, Rect area, const PolarPlot& plot);

/// A figure holding `plot` alone.
Figure polar_plot_figure(const PolarPlot& plot, int width, int height);

}  // namespace rheomag::plot
