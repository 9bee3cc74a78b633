#include "figures/gap_profile.hpp"

#include <cmath>
#include <cstdio>

#include "figures/scaled.hpp"
#include "plot/line_plot.hpp"

namespace rheomag::figures {

namespace {

/// "label = 0.706 T".
std::string tesla_label(const char* label, double value) {
  char text[96];
  std::snprintf(text, sizeof text, "%s = %.3f T", label, value);
  return text;
}

}  // namespace

plot::Figure gap_profile_figure(const magnetostatics::GapResult& gap, int width, int height) {
  const bool annular = gap.kind == mesh::GapKind::annular;
  plot::LinePlot p;
  p.title = "B along gap " + gap.name +
            (annular ? " (annular: n = r, t = z)" : " (radial: n = z, t = r)");
  p.x_label = std::string("s along the gap [mm] (from ") + (annular ? "low z" : "low r") + ")";
  p.y_label = "B [T]";
  p.y_from_zero = true;
  const auto& mid = gap.profile;
  std::vector<double> magnitude;
  for (std::size_t i = 0; i < mid.s.size(); ++i)
    magnitude.push_back(std::hypot(mid.b_n[i], mid.b_t[i]));
  const std::vector<double> s_mm = scaled(mid.s, 1e3);
  p.series.push_back({"|B| mid-line", s_mm, magnitude, plot::series_colour(5)});
  p.series.push_back({"B_n mid-line", s_mm, mid.b_n, plot::series_colour(0)});
  p.series.push_back({"B_t mid-line", s_mm, mid.b_t, plot::series_colour(1)});
  const char* wall_names[2] = {annular ? "inner wall" : "lower wall",
                               annular ? "outer wall" : "upper wall"};
  for (int w = 0; w < 2; ++w) {
    const auto& wall = gap.walls[w];
    if (wall.s.empty()) continue;
    const std::vector<double> ws = scaled(wall.s, 1e3);
    p.series.push_back(
        {std::string("B_n ") + wall_names[w], ws, wall.b_n, plot::series_colour(2 + w), true});
    p.series.push_back({std::string("B_t ") + wall_names[w], ws, wall.b_t,
                        plot::series_colour(w == 0 ? 4 : 1), true});
  }
  if (std::isfinite(gap.line_b.average))
    p.guides.push_back(
        {false, gap.line_b.average, tesla_label("mid-line |B| mean", gap.line_b.average)});
  if (std::isfinite(gap.b.average))
    p.guides.push_back(
        {false, gap.b.average, tesla_label("B_avg (area)", gap.b.average), {0.6, 0.1, 0.1}});
  return plot::line_plot_figure(p, width, height);
}

}  // namespace rheomag::figures
