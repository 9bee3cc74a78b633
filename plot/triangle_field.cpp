#include "plot/triangle_field.hpp"

#include <algorithm>

namespace rheomag::plot {

void fill_triangles(cairo_t* cr, const Axes& axes, const TriangleMesh& mesh,
                    const std::vector<double>& values, const ColourMap& colours) {
  std::vector<std::vector<int>> by_bin(colours.bins());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    by_bin[colours.bin(values[t])].push_back(static_cast<int>(t));
  cairo_save(cr);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
  for (int bin = 0; bin < colours.bins(); ++bin) {
    if (by_bin[bin].empty()) continue;
    for (int t : by_bin[bin]) {
      const auto& tri = mesh.triangles[t];
      // Each triangle is traced counter-clockwise on screen so that the winding rule fills the
      // union of touching triangles without holes.
      auto p0 = axes.to_px(mesh.points[tri[0]][0], mesh.points[tri[0]][1]);
      auto p1 = axes.to_px(mesh.points[tri[1]][0], mesh.points[tri[1]][1]);
      auto p2 = axes.to_px(mesh.points[tri[2]][0], mesh.points[tri[2]][1]);
      const double cross = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0]);
      if (cross < 0.0) std::swap(p1, p2);
      cairo_move_to(cr, p0[0], p0[1]);
      cairo_line_to(cr, p1[0], p1[1]);
      cairo_line_to(cr, p2[0], p2[1]);
      cairo_close_path(cr);
    }
    set_colour(cr, colours.bin_colour(bin));
    // A hairline of the same colour covers the seams a browser's anti-aliasing of the SVG would
    // show between neighbouring triangles.
    cairo_fill_preserve(cr);
    cairo_set_line_width(cr, 0.5);
    cairo_stroke(cr);
  }
  cairo_restore(cr);
}

std::vector<double> centred_levels(double low, double high, int count) {
  std::vector<double> levels;
  for (int k = 0; k < count; ++k) levels.push_back(low + (k + 0.5) * (high - low) / count);
  return levels;
}

std::vector<ContourSegment> contour_segments(const TriangleMesh& mesh,
                                             const std::vector<double>& node_values,
                                             const std::vector<double>& levels) {
  std::vector<ContourSegment> segments;
  for (const auto& tri : mesh.triangles) {
    const double v[3] = {node_values[tri[0]], node_values[tri[1]], node_values[tri[2]]};
    const double low = std::min({v[0], v[1], v[2]}), high = std::max({v[0], v[1], v[2]});
    for (int level = 0; level < static_cast<int>(levels.size()); ++level) {
      const double c = levels[level];
      if (c < low || c > high) continue;
      std::array<double, 2> ends[2];
      int found = 0;
      for (int e = 0; e < 3 && found < 2; ++e) {
        const int i = e, j = (e + 1) % 3;
        if ((v[i] >= c) == (v[j] >= c)) continue;
        const double t = (c - v[i]) / (v[j] - v[i]);
        const auto& a = mesh.points[tri[i]];
        const auto& b = mesh.points[tri[j]];
        ends[found++] = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
      }
      if (found == 2) segments.push_back({ends[0], ends[1], level});
    }
  }
  return segments;
}

void draw_segments(cairo_t* cr, const Axes& axes, const std::vector<ContourSegment>& segments,
                   Rgb colour, double width) {
  cairo_save(cr);
  set_colour(cr, colour);
  cairo_set_line_width(cr, width);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (const ContourSegment& s : segments) {
    const auto a = axes.to_px(s.a[0], s.a[1]);
    const auto b = axes.to_px(s.b[0], s.b[1]);
    cairo_move_to(cr, a[0], a[1]);
    cairo_line_to(cr, b[0], b[1]);
  }
  cairo_stroke(cr);
  cairo_restore(cr);
}

}  // namespace rheomag::plot
