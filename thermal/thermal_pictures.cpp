// The temperature map and the heating curves of a thermal report.

#include "thermal/thermal_pictures.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "core/error.hpp"
#include "plot/axes.hpp"
#include "plot/colour_bar.hpp"
#include "plot/colour_map.hpp"
#include "plot/line_plot.hpp"
#include "plot/triangle_field.hpp"

namespace rheomag::thermal {

namespace {

/// The active triangles on their corner nodes (mm), their corner temperatures and mean values.
struct ActiveField {
  plot::TriangleMesh mesh;
  std::vector<double> node_temperature, triangle_temperature;
  std::vector<int> region;  ///< per triangle
};

ActiveField active_field(const ThermalReport& r) {
  ActiveField f;
  std::vector<int> point_of_node(r.mesh.nodes.size(), -1);
  for (std::size_t e = 0; e < r.mesh.triangles.size(); ++e) {
    if (!r.regions[r.mesh.region[e]].active) continue;
    std::array<int, 3> corners{};
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
      const int node = r.mesh.triangles[e][i];
      if (point_of_node[node] < 0) {
        point_of_node[node] = static_cast<int>(f.mesh.points.size());
        f.mesh.points.push_back({1e3 * r.mesh.nodes[node].r, 1e3 * r.mesh.nodes[node].z});
        f.node_temperature.push_back(r.field.temperature[node]);
      }
      corners[i] = point_of_node[node];
      sum += r.field.temperature[node];
    }
    f.mesh.triangles.push_back(corners);
    f.triangle_temperature.push_back(sum / 3.0);
    f.region.push_back(r.mesh.region[e]);
  }
  return f;
}

/// The edges between two regions and the outer edges of the active triangles.
std::vector<plot::ContourSegment> outlines(const ActiveField& f) {
  std::map<std::pair<int, int>, std::pair<int, int>> edges;  // -> (region, -2 when interior)
  for (std::size_t e = 0; e < f.mesh.triangles.size(); ++e)
    for (int i = 0; i < 3; ++i) {
      int a = f.mesh.triangles[e][i], b = f.mesh.triangles[e][(i + 1) % 3];
      if (a > b) std::swap(a, b);
      auto [it, inserted] = edges.try_emplace({a, b}, f.region[e], 0);
      if (!inserted && it->second.first == f.region[e]) it->second.first = -2;
    }
  std::vector<plot::ContourSegment> out;
  for (const auto& [edge, state] : edges)
    if (state.first != -2) out.push_back({f.mesh.points[edge.first], f.mesh.points[edge.second]});
  return out;
}

}  // namespace

TemperatureMap draw_temperature_map(const ThermalReport& report, int isotherms, int bins, int width,
                                    int height) {
  const ActiveField f = active_field(report);
  if (f.mesh.triangles.empty()) throw InputError("thermal: no region of the thermal model to draw");
  std::vector<double> xs, ys;
  for (const auto& p : f.mesh.points) xs.push_back(p[0]), ys.push_back(p[1]);
  const auto [lo, hi] = std::minmax_element(f.node_temperature.begin(), f.node_temperature.end());
  const double low = *lo, high = *hi > *lo ? *hi : *lo + 1.0;  // a uniform field: one band
  const plot::ColourMap colours(low, high, bins);
  const double w = width, h = height;
  const plot::Rect frame{70.0, 40.0, w - 70.0 - 110.0, h - 40.0 - 55.0};
  const plot::Axes axes =
      plot::Axes::equal_aspect(frame, plot::range_of({xs}, 0.03), plot::range_of({ys}, 0.03));
  plot::Figure figure(width, height);
  cairo_t* cr = figure.cr();
  cairo_save(cr);
  axes.clip(cr);
  plot::fill_triangles(cr, axes, f.mesh, f.triangle_temperature, colours);
  if (isotherms > 0 && *hi > *lo)
    plot::draw_segments(cr, axes,
                        plot::contour_segments(f.mesh, f.node_temperature,
                                               plot::centred_levels(low, high, isotherms)),
                        {0.0, 0.0, 0.0}, 0.8);
  plot::draw_segments(cr, axes, outlines(f), {0.85, 0.85, 0.85}, 0.8);
  cairo_restore(cr);
  axes.draw(cr, report.planar ? "x [mm]" : "r [mm]", report.planar ? "y [mm]" : "z [mm]");
  const std::string state =
      report.transient ? "after " + plot::tick_label(report.field.time, 1.0) + " s" : "steady";
  plot::draw_text(cr, report.case_name + ": temperature (" + state + "), isotherms", 0.5 * w, 12.0,
                  14.0, 0.5, 0.0);
  plot::draw_colour_bar(cr, {w - 85.0, frame.y + 20.0, 22.0, frame.height - 20.0}, colours,
                        "T [deg C]");
  return {std::move(figure), axes, colours};
}

plot::Figure draw_heating_curves(const ThermalReport& report, int width, int height) {
  if (!report.transient)
    throw InputError("thermal: the heating curves need a transient (--duration)");
  plot::LinePlot p;
  p.title = report.case_name + ": heating from " + plot::tick_label(report.ambient, 1.0) + " deg C";
  p.x_label = "t [s]";
  p.y_label = "T [deg C]";
  plot::Series coil_max, coil_mean, fluid_max, fluid_mean;
  coil_max.name = "coil, hottest point";
  coil_mean.name = "coil, mean";
  fluid_max.name = "fluid, hottest point";
  fluid_mean.name = "fluid, mean";
  for (const DeviceSample& s : report.transient->samples) {
    for (plot::Series* series : {&coil_max, &coil_mean, &fluid_max, &fluid_mean})
      series->x.push_back(s.time);
    coil_max.y.push_back(s.temperatures.coil_max);
    coil_mean.y.push_back(s.temperatures.coil_mean);
    fluid_max.y.push_back(s.temperatures.fluid_max);
    fluid_mean.y.push_back(s.temperatures.fluid_mean);
  }
  coil_max.colour = coil_mean.colour = plot::series_colour(0);
  fluid_max.colour = fluid_mean.colour = plot::series_colour(1);
  coil_mean.dashed = fluid_mean.dashed = true;
  for (plot::Series* series : {&coil_max, &coil_mean, &fluid_max, &fluid_mean})
    if (std::any_of(series->y.begin(), series->y.end(), [](double v) { return std::isfinite(v); }))
      p.series.push_back(std::move(*series));
  if (report.limit)
    p.guides.push_back({false, *report.limit, "limit " + plot::tick_label(*report.limit, 1.0)});
  if (report.transient->time_to_limit)
    p.guides.push_back(
        {true, *report.transient->time_to_limit,
         "limit reached at " + plot::tick_label(*report.transient->time_to_limit, 0.1) + " s"});
  return plot::line_plot_figure(p, width, height);
}

}  // namespace rheomag::thermal
