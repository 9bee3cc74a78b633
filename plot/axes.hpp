#pragma once
// Axes: the map from data coordinates into a pixel rectangle, with ticks, labels and text.

#include <cairo.h>

#include <array>
#include <string>
#include <vector>

#include "plot/colour_map.hpp"

namespace rheomag::plot {

/// A rectangle in pixels (origin top left, y down).
struct Rect {
  double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
};

/// A closed interval of data values.
struct Range {
  double low = 0.0, high = 1.0;
};

/// Tick values inside [low, high] at a step of 1, 2 or 5 times a power of ten, about `target`
/// of them.
std::vector<double> nice_ticks(double low, double high, int target);

/// A range that holds every finite value of `values`, padded by `pad` of its
/// length on both sides; a unit range around a single value, [0, 1] when there is none.
Range range_of(const std::vector<std::vector<double>>& values, double pad);

/// Maps data (x, y) into a pixel rectangle, y up.
class Axes {
 public:
  /// Data ranges x and y drawn in the pixel rectangle `frame`.
  Axes(Rect frame, Range x, Range y);
  /// Axes whose ranges hold `x` and `y` and are widened (about their centres) so that one data
  /// unit is as long on both axes: true aspect ratio.
  static Axes equal_aspect(Rect frame, Range x, Range y);
  /// Pixel position of data (x, y).
  std::array<double, 2> to_px(double x, double y) const;
  /// Data position of pixel (px, py).
  std::array<double, 2> to_data(double px, double py) const;
  /// The pixel rectangle.
  const Rect& frame() const { return frame_; }
  /// The x range.
  Range x() const { return x_; }
  /// The y range.
  Range y() const { return y_; }
  /// Clips drawing to the frame (undo with cairo_reset_clip).
  void clip(cairo_t* cr) const;
  /// Draws the frame, ticks with their labels and the axis labels.
  void draw(cairo_t* cr, const std::string& x_label, const std::string& y_label) const;

 private:
  Rect frame_;
  Range x_, y_;
};

/// Sets the source colour.
void set_colour(cairo_t* cr, Rgb c, double alpha = 1.0);

/// Draws `text` at font size `size` with its anchor at (x, y): align_x 0 = left edge, 0.5 =
/// centre, 1 = right edge; align_y 0 = top, 0.5 = middle, 1 = baseline. `halo` draws a white
/// rim first, so that the text stays readable over a colour field.
void draw_text(cairo_t* cr, const std::string& text, double x, double y, double size,
               double align_x, double align_y, bool halo = false);

/// A tick label: `value` with as many decimals as `step` needs ("0.25", "-3", "1e-05").
std::string tick_label(double value, double step);

}  // namespace rheomag::plot
