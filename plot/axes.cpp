#include "plot/axes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rheomag::plot {

std::vector<double> nice_ticks(double low, double high, int target) {
  std::vector<double> ticks;
  if (!(high > low) || !std::isfinite(low) || !std::isfinite(high) || target < 1) return ticks;
  const double raw = (high - low) / target;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10.0 * power;
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * power >= raw) {
      step = m * power;
      break;
    }
  }
  const double first = std::ceil(low / step - 1e-9);
  for (double k = first; k * step <= high + 1e-9 * step; k += 1.0) {
    const double v = k * step;
    ticks.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
  }
  return ticks;
}

Range range_of(const std::vector<std::vector<double>>& values, double pad) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const auto& list : values) {
    for (double v : list) {
      if (!std::isfinite(v)) continue;
      low = std::min(low, v), high = std::max(high, v);
    }
  }
  if (!std::isfinite(low)) return {0.0, 1.0};
  if (high - low <= 1e-12 * std::max(1.0, std::abs(high))) {
    const double half = std::max(0.5 * std::abs(high), 0.5);
    return {low - half, high + half};
  }
  const double d = pad * (high - low);
  return {low - d, high + d};
}

Axes::Axes(Rect frame, Range x, Range y) : frame_(frame), x_(x), y_(y) {}

Axes Axes::equal_aspect(Rect frame, Range x, Range y) {
  const double scale =
      std::min(frame.width / (x.high - x.low), frame.height / (y.high - y.low));  // px per unit
  const double half_x = 0.5 * frame.width / scale, half_y = 0.5 * frame.height / scale;
  const double cx = 0.5 * (x.low + x.high), cy = 0.5 * (y.low + y.high);
  return Axes(frame, {cx - half_x, cx + half_x}, {cy - half_y, cy + half_y});
}

std::array<double, 2> Axes::to_px(double x, double y) const {
  return {frame_.x + (x - x_.low) / (x_.high - x_.low) * frame_.width,
          frame_.y + frame_.height - (y - y_.low) / (y_.high - y_.low) * frame_.height};
}

std::array<double, 2> Axes::to_data(double px, double py) const {
  return {x_.low + (px - frame_.x) / frame_.width * (x_.high - x_.low),
          y_.low + (frame_.y + frame_.height - py) / frame_.height * (y_.high - y_.low)};
}

void Axes::clip(cairo_t* cr) const {
  cairo_rectangle(cr, frame_.x, frame_.y, frame_.width, frame_.height);
  cairo_clip(cr);
}

void set_colour(cairo_t* cr, Rgb c, double alpha) {
  cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

std::string tick_label(double value, double step) {
  char text[64];
  const double magnitude = std::max(std::abs(value), step);
  if (magnitude >= 1e5 || step < 1e-4) {
    std::snprintf(text, sizeof text, "%.3g", value);
  } else {
    const int decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
  }
  return text;
}

void draw_text(cairo_t* cr, const std::string& text, double x, double y, double size,
               double align_x, double align_y, bool halo) {
  cairo_save(cr);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  cairo_font_extents_t font;
  cairo_font_extents(cr, &font);
  const double left = x - align_x * extents.x_advance;
  // align_y: 0 puts the top of capitals at y, 0.5 their middle, 1 the baseline.
  const double drawn_baseline = y + (1.0 - std::clamp(align_y, 0.0, 1.0)) * font.ascent * 0.8;
  cairo_move_to(cr, left, drawn_baseline);
  if (halo) {
    cairo_text_path(cr, text.c_str());
    cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, 0.85);
    cairo_set_line_width(cr, 3.0);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_stroke(cr);
    cairo_move_to(cr, left, drawn_baseline);
  }
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  cairo_show_text(cr, text.c_str());
  cairo_restore(cr);
}

void Axes::draw(cairo_t* cr, const std::string& x_label, const std::string& y_label) const {
  cairo_save(cr);
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, frame_.x, frame_.y, frame_.width, frame_.height);
  cairo_stroke(cr);
  const double font = 12.0;
  const std::vector<double> xs = nice_ticks(x_.low, x_.high, std::max(2, int(frame_.width / 90)));
  const std::vector<double> ys = nice_ticks(y_.low, y_.high, std::max(2, int(frame_.height / 60)));
  const double x_step = xs.size() > 1 ? xs[1] - xs[0] : 1.0;
  const double y_step = ys.size() > 1 ? ys[1] - ys[0] : 1.0;
  const double bottom = frame_.y + frame_.height;
  for (double v : xs) {
    const double px = to_px(v, y_.low)[0];
    cairo_move_to(cr, px, bottom);
    cairo_line_to(cr, px, bottom - 5.0);
    cairo_stroke(cr);
    draw_text(cr, tick_label(v, x_step), px, bottom + 4.0, font, 0.5, 0.0);
  }
  double widest = 0.0;
  for (double v : ys) {
    const double py = to_px(x_.low, v)[1];
    cairo_move_to(cr, frame_.x, py);
    cairo_line_to(cr, frame_.x + 5.0, py);
    cairo_stroke(cr);
    const std::string label = tick_label(v, y_step);
    cairo_set_font_size(cr, font);
    cairo_text_extents_t extents;
    cairo_text_extents(cr, label.c_str(), &extents);
    widest = std::max(widest, extents.x_advance);
    draw_text(cr, label, frame_.x - 4.0, py, font, 1.0, 0.5);
  }
  draw_text(cr, x_label, frame_.x + 0.5 * frame_.width, bottom + 22.0, 13.0, 0.5, 0.0);
  cairo_save(cr);
  cairo_translate(cr, frame_.x - widest - 12.0, frame_.y + 0.5 * frame_.height);
  cairo_rotate(cr, -M_PI / 2.0);
  draw_text(cr, y_label, 0.0, 0.0, 13.0, 0.5, 1.0);
  cairo_restore(cr);
  cairo_restore(cr);
}

}  // namespace rheomag::plot
