#include "figures/transient_step.hpp"

#include <cstdio>

#include "figures/scaled.hpp"
#include "plot/line_plot.hpp"

namespace rheomag::figures {

namespace {

/// The t63 / t90 guides [ms] of the flux linkage, those that were reached.
std::vector<plot::Guide> rise_guides(const transient::TransientResult& r) {
  std::vector<plot::Guide> guides;
  char text[64];
  if (r.t63) {
    std::snprintf(text, sizeof text, "t63 = %.3g ms", 1e3 * *r.t63);
    guides.push_back({true, 1e3 * *r.t63, text});
  }
  if (r.t90) {
    std::snprintf(text, sizeof text, "t90 = %.3g ms", 1e3 * *r.t90);
    guides.push_back({true, 1e3 * *r.t90, text, {0.6, 0.1, 0.1}});
  }
  return guides;
}

}  // namespace

plot::Figure transient_step_figure(const transient::TransientResult& result,
                                   const std::string& title, int width, int height) {
  const std::vector<double> t_ms = scaled(result.time, 1e3);
  const std::vector<plot::Guide> guides = rise_guides(result);
  plot::LinePlot current;
  current.title = title + ": coil current";
  current.x_label = "t [ms]";
  current.y_label = "I [A]";
  current.series.push_back({"I(t)", t_ms, result.current, plot::series_colour(0)});
  current.guides = guides;
  plot::LinePlot lambda;
  lambda.title = "Flux linkage (t63, t90 of its change)";
  lambda.x_label = "t [ms]";
  lambda.y_label = "lambda [mWb]";
  lambda.series.push_back(
      {"lambda(t)", t_ms, scaled(result.flux_linkage, 1e3), plot::series_colour(1)});
  lambda.guides = guides;
  lambda.guides.push_back({false, 1e3 * result.final_flux_linkage, "static lambda at the end"});
  plot::LinePlot gaps;
  gaps.title = "Mean |B| in each fluid gap";
  gaps.x_label = "t [ms]";
  gaps.y_label = "|B| [T]";
  gaps.y_from_zero = true;
  for (std::size_t g = 0; g < result.gaps.size(); ++g) {
    gaps.series.push_back({result.gaps[g].name, t_ms, result.gaps[g].b_avg,
                           plot::series_colour(static_cast<int>(g) + 2)});
  }
  gaps.guides = guides;
  plot::Figure figure(width, height);
  const double third = height / 3.0;
  plot::draw_line_plot(figure.cr(), {0.0, 0.0, double(width), third}, current);
  plot::draw_line_plot(figure.cr(), {0.0, third, double(width), third}, lambda);
  plot::draw_line_plot(figure.cr(), {0.0, 2.0 * third, double(width), third}, gaps);
  return figure;
}

}  // namespace rheomag::figures
