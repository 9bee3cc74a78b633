#include "plot/polar_plot.hpp"

#include <algorithm>
#include <cmath>

namespace rheomag::plot {

void draw_polar_plot(cairo_t* cr, Rect area, const PolarPlot& plot) {
  double top = 0.0;
  for (const PolarSeries& s : plot.series) {
    for (double r : s.radius) {
      if (std::isfinite(r)) top = std::max(top, r);
    }
  }
  if (!(top > 0.0)) top = 1.0;
  const std::vector<double> rings = nice_ticks(0.0, top, 4);
  const double step = rings.size() > 1 ? rings[1] - rings[0] : top;
  const double outer = std::ceil(top / step - 1e-9) * step;
  const double legend = 170.0;
  const double cx = area.x + 0.5 * (area.width - legend), cy = area.y + 0.5 * area.height + 10.0;
  const double scale = 0.5 * std::min(area.width - legend, area.height - 40.0) * 0.82 / outer;
  cairo_save(cr);
  draw_text(cr, plot.title, area.x + 0.5 * area.width, area.y + 10.0, 14.0, 0.5, 0.0);
  cairo_set_line_width(cr, 0.8);
  for (double r = step; r <= outer + 1e-9 * step; r += step) {
    cairo_set_source_rgb(cr, 0.8, 0.8, 0.8);
    cairo_new_sub_path(cr);
    cairo_arc(cr, cx, cy, r * scale, 0.0, 2.0 * M_PI);
    cairo_stroke(cr);
    draw_text(cr, tick_label(r, step), cx + 3.0, cy - r * scale - 2.0, 10.0, 0.0, 1.0, true);
  }
  for (int deg = 0; deg < 360; deg += 30) {
    const double a = deg * M_PI / 180.0;
    cairo_set_source_rgb(cr, 0.8, 0.8, 0.8);
    cairo_move_to(cr, cx, cy);
    cairo_line_to(cr, cx + outer * scale * std::cos(a), cy - outer * scale * std::sin(a));
    cairo_stroke(cr);
    const double label = outer * scale + 14.0;
    draw_text(cr, std::to_string(deg) + "\u00b0", cx + label * std::cos(a),
              cy - label * std::sin(a), 11.0, 0.5, 0.5);
  }
  draw_text(cr, plot.unit, cx + 3.0, cy + 4.0, 11.0, 0.0, 0.0, true);
  double row = area.y + 40.0;
  for (const PolarSeries& s : plot.series) {
    set_colour(cr, s.colour);
    cairo_set_line_width(cr, 1.8);
    bool first = true;
    for (std::size_t i = 0; i < std::min(s.angle.size(), s.radius.size()); ++i) {
      if (!std::isfinite(s.radius[i])) continue;
      const double x = cx + s.radius[i] * scale * std::cos(s.angle[i]);
      const double y = cy - s.radius[i] * scale * std::sin(s.angle[i]);
      first ? cairo_move_to(cr, x, y) : cairo_line_to(cr, x, y);
      first = false;
    }
    cairo_close_path(cr);
    cairo_stroke(cr);
    for (std::size_t i = 0; i < std::min(s.angle.size(), s.radius.size()); ++i) {
      if (!std::isfinite(s.radius[i])) continue;
      cairo_arc(cr, cx + s.radius[i] * scale * std::cos(s.angle[i]),
                cy - s.radius[i] * scale * std::sin(s.angle[i]), 2.2, 0.0, 2.0 * M_PI);
      cairo_fill(cr);
    }
    cairo_move_to(cr, area.x + area.width - legend + 10.0, row + 6.0);
    cairo_line_to(cr, area.x + area.width - legend + 34.0, row + 6.0);
    cairo_stroke(cr);
    draw_text(cr, s.name, area.x + area.width - legend + 40.0, row + 6.0, 11.0, 0.0, 0.5);
    row += 16.0;
  }
  cairo_restore(cr);
}

Figure polar_plot_figure(const PolarPlot& plot, int width, int height) {
  Figure figure(width, height);
  draw_polar_plot(figure.cr(), {0.0, 0.0, double(width), double(height)}, plot);
  return figure;
}

}  // namespace rheomag::plot
