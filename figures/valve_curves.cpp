#include "figures/valve_curves.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plot/line_plot.hpp"

namespace rheomag::figures {

plot::Figure valve_curves_figure(const valve::ValveReport& report, int width, int height) {
  const std::size_t per_current = std::max<std::size_t>(1, report.flows_per_current);
  const std::size_t currents = report.points.size() / per_current;
  constexpr double kLitresPerMinute = 6e4;  // per m^3/s
  constexpr double kBar = 1e-5;             // per Pa
  plot::LinePlot dp;
  dp.title = report.case_name + ": pressure drop (" + report.fluid + ")";
  dp.x_label = "Q [L/min]";
  dp.y_label = "dp [bar]";
  dp.y_from_zero = true;
  for (std::size_t k = 0; k < currents; ++k) {
    plot::Series s;
    char name[64];
    std::snprintf(name, sizeof name, "I = %g A", report.points[k * per_current].current);
    s.name = name;
    s.colour = plot::series_colour(static_cast<int>(k));
    s.markers = true;
    for (std::size_t f = 0; f < per_current; ++f) {
      const valve::ValvePoint& p = report.points[k * per_current + f];
      s.x.push_back(kLitresPerMinute * p.flow);
      s.y.push_back(kBar * p.dp_total);
    }
    dp.series.push_back(s);
  }
  plot::Figure figure(width, height);
  if (currents < 2) {
    plot::draw_line_plot(figure.cr(), {0.0, 0.0, double(width), double(height)}, dp);
    return figure;
  }
  // The currents of smallest and largest magnitude.
  std::size_t low = 0, high = 0;
  for (std::size_t k = 0; k < currents; ++k) {
    const double i = std::abs(report.points[k * per_current].current);
    if (i < std::abs(report.points[low * per_current].current)) low = k;
    if (i > std::abs(report.points[high * per_current].current)) high = k;
  }
  plot::LinePlot range;
  char title[128];
  std::snprintf(title, sizeof title, "Dynamic range dp(%g A) / dp(%g A)",
                report.points[high * per_current].current,
                report.points[low * per_current].current);
  range.title = title;
  range.x_label = "Q [L/min]";
  range.y_label = "dynamic range [-]";
  range.y_from_zero = true;
  // Named, so that both panels keep the legend's width and their Q axes line up.
  plot::Series ratio{"dp ratio", {}, {}, plot::series_colour(0), false, true};
  for (std::size_t f = 0; f < per_current; ++f) {
    const valve::ValvePoint& on = report.points[high * per_current + f];
    const valve::ValvePoint& off = report.points[low * per_current + f];
    ratio.x.push_back(kLitresPerMinute * on.flow);
    ratio.y.push_back(off.dp_total > 0.0 ? on.dp_total / off.dp_total : NAN);
  }
  range.series.push_back(ratio);
  const double top = 0.62 * height;
  plot::draw_line_plot(figure.cr(), {0.0, 0.0, double(width), top}, dp);
  plot::draw_line_plot(figure.cr(), {0.0, top, double(width), height - top}, range);
  return figure;
}

}  // namespace rheomag::figures
