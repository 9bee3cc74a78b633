#pragma once
// Line plots: several named series against one x axis, with guide lines and a legend.

#include <string>
#include <vector>

#include "plot/axes.hpp"
#include "plot/colour_map.hpp"
#include "plot/figure.hpp"

namespace rheomag::plot {

/// One curve: points (x[i], y[i]); non-finite points break the line.
struct Series {
  std::string name;
  std::vector<double> x, y;
  Rgb colour;
  bool dashed = false;
  bool markers = false;  ///< a dot at every point
};

/// A labelled straight line across the plot: x = value (vertical) or y = value.
struct Guide {
  bool vertical = false;
  double value = 0.0;
  std::string label;
  Rgb colour{0.35, 0.35, 0.35};
};

/// What one line plot shows.
struct LinePlot {
  std::string title, x_label, y_label;
  std::vector<Series> series;
  std::vector<Guide> guides;
  bool y_from_zero = false;  ///< the y range includes 0
};

/// The i-th colour of a palette of distinct, dark-enough line colours (cycles).
Rgb series_colour(int i);

/// Draws `plot` inside `area` of `cr`: title, axes, guides, curves, legend.
void draw_line_plot(cairo_t* cr, Rect area, const LinePlot& plot);

/// A figure holding `plot` alone.
Figure line_plot_figure(const LinePlot& plot, int width, int height);

}  // namespace rheomag::plot
