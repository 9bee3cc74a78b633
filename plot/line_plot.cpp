#include "plot/line_plot.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace rheomag::plot {

Rgb series_colour(int i) {
  static constexpr std::array<Rgb, 6> kPalette{{{0.12, 0.38, 0.70},
                                                {0.85, 0.37, 0.01},
                                                {0.17, 0.55, 0.17},
                                                {0.75, 0.11, 0.17},
                                                {0.50, 0.32, 0.65},
                                                {0.45, 0.33, 0.25}}};
  return kPalette[static_cast<std::size_t>(i) % kPalette.size()];
}

namespace {

/// The curve of `s` as a path through its finite points (a gap where a point is not finite).
void trace_series(cairo_t* cr, const Axes& axes, const Series& s) {
  bool pen_down = false;
  for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
    if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
      pen_down = false;
      continue;
    }
    const auto p = axes.to_px(s.x[i], s.y[i]);
    if (pen_down) {
      cairo_line_to(cr, p[0], p[1]);
    } else {
      cairo_move_to(cr, p[0], p[1]);
    }
    pen_down = true;
  }
}

}  // namespace

void draw_line_plot(cairo_t* cr, Rect area, const LinePlot& plot) {
  std::vector<std::vector<double>> xs, ys;
  for (const Series& s : plot.series) xs.push_back(s.x), ys.push_back(s.y);
  for (const Guide& g : plot.guides) (g.vertical ? xs : ys).push_back({g.value});
  if (plot.y_from_zero) ys.push_back({0.0});
  Range x = range_of(xs, 0.0);
  Range y = range_of(ys, 0.06);
  bool legend = false;
  for (const Series& s : plot.series) legend = legend || !s.name.empty();
  const double legend_width = legend ? 150.0 : 0.0;
  const Rect frame{area.x + 78.0, area.y + 34.0, area.width - 96.0 - legend_width,
                   area.height - 84.0};
  const Axes axes(frame, x, y);
  cairo_save(cr);
  draw_text(cr, plot.title, area.x + 0.5 * area.width, area.y + 10.0, 14.0, 0.5, 0.0);
  axes.draw(cr, plot.x_label, plot.y_label);
  axes.clip(cr);
  int horizontal = 0;
  for (const Guide& g : plot.guides) {
    set_colour(cr, g.colour);
    cairo_set_line_width(cr, 1.0);
    const double dash[] = {2.0, 3.0};
    cairo_set_dash(cr, dash, 2, 0.0);
    const auto a = g.vertical ? axes.to_px(g.value, y.low) : axes.to_px(x.low, g.value);
    const auto b = g.vertical ? axes.to_px(g.value, y.high) : axes.to_px(x.high, g.value);
    cairo_move_to(cr, a[0], a[1]);
    cairo_line_to(cr, b[0], b[1]);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
    if (g.vertical) {
      draw_text(cr, g.label, a[0] + 3.0, frame.y + 4.0, 11.0, 0.0, 0.0, true);
    } else if (horizontal++ % 2 == 0) {  // alternate ends, so that close guides stay legible
      draw_text(cr, g.label, frame.x + frame.width - 4.0, a[1] - 3.0, 11.0, 1.0, 1.0, true);
    } else {
      draw_text(cr, g.label, frame.x + 4.0, a[1] + 3.0, 11.0, 0.0, 0.0, true);
    }
  }
  for (const Series& s : plot.series) {
    set_colour(cr, s.colour);
    cairo_set_line_width(cr, 1.8);
    const double dash[] = {6.0, 4.0};
    cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0.0);
    trace_series(cr, axes, s);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
    if (!s.markers) continue;
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      const auto p = axes.to_px(s.x[i], s.y[i]);
      cairo_arc(cr, p[0], p[1], 2.5, 0.0, 2.0 * M_PI);
      cairo_fill(cr);
    }
  }
  cairo_reset_clip(cr);
  // Legend: right of the frame, one line per named series.
  const double left = frame.x + frame.width + 10.0;
  double row = frame.y + 8.0;
  for (const Series& s : plot.series) {
    if (s.name.empty()) continue;
    set_colour(cr, s.colour);
    cairo_set_line_width(cr, 2.0);
    const double dash[] = {6.0, 4.0};
    cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0.0);
    cairo_move_to(cr, left, row + 6.0);
    cairo_line_to(cr, left + 24.0, row + 6.0);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
    draw_text(cr, s.name, left + 30.0, row + 6.0, 11.0, 0.0, 0.5);
    row += 16.0;
  }
  cairo_restore(cr);
}

Figure line_plot_figure(const LinePlot& plot, int width, int height) {
  Figure figure(width, height);
  draw_line_plot(figure.cr(), {0.0, 0.0, double(width), double(height)}, plot);
  return figure;
}

}  // namespace rheomag::plot
