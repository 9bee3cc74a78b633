#include "plot/colour_bar.hpp"

namespace rheomag::plot {

void draw_colour_bar(cairo_t* cr, Rect area, const ColourMap& colours, const std::string& label) {
  cairo_save(cr);
  const double h = area.height / colours.bins();
  for (int i = 0; i < colours.bins(); ++i) {
    cairo_rectangle(cr, area.x, area.y + area.height - (i + 1) * h, area.width, h);
    set_colour(cr, colours.bin_colour(i));
    cairo_fill(cr);
  }
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, area.x, area.y, area.width, area.height);
  cairo_stroke(cr);
  const Axes scale({area.x, area.y, area.width, area.height}, {0.0, 1.0},
                   {colours.low(), colours.high()});
  const std::vector<double> ticks = nice_ticks(colours.low(), colours.high(), 8);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
  for (double v : ticks) {
    const double py = scale.to_px(0.0, v)[1];
    cairo_move_to(cr, area.x + area.width, py);
    cairo_line_to(cr, area.x + area.width + 4.0, py);
    cairo_stroke(cr);
    draw_text(cr, tick_label(v, step), area.x + area.width + 6.0, py, 11.0, 0.0, 0.5);
  }
  draw_text(cr, label, area.x + 0.5 * area.width, area.y - 8.0, 12.0, 0.5, 1.0);
  cairo_restore(cr);
}

}  // namespace rheomag::plot
