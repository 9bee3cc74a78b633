#include "figures/inductance.hpp"

#include "plot/line_plot.hpp"

namespace rheomag::figures {

plot::Figure inductance_figure(const std::vector<magnetostatics::SweepPoint>& sweep,
                               const std::string& circuit, int width, int height) {
  std::vector<double> current, lambda, secant, incremental;
  for (const magnetostatics::SweepPoint& p : sweep) {
    current.push_back(p.current);
    lambda.push_back(1e3 * p.flux_linkage);
    secant.push_back(1e3 * p.secant_inductance);
    incremental.push_back(1e3 * p.incremental_inductance);
  }
  plot::LinePlot top;
  top.title = "Flux linkage of circuit " + circuit;
  top.x_label = "I [A]";
  top.y_label = "lambda [mWb]";
  top.y_from_zero = true;
  top.series.push_back({"lambda(I)", current, lambda, plot::series_colour(0), false, true});
  plot::LinePlot bottom;
  bottom.title = "Inductance of circuit " + circuit;
  bottom.x_label = "I [A]";
  bottom.y_label = "L [mH]";
  bottom.y_from_zero = true;
  bottom.series.push_back({"lambda / I", current, secant, plot::series_colour(1), false, true});
  bottom.series.push_back(
      {"d lambda / dI", current, incremental, plot::series_colour(2), true, true});
  plot::Figure figure(width, height);
  const double half = 0.5 * height;
  plot::draw_line_plot(figure.cr(), {0.0, 0.0, double(width), half}, top);
  plot::draw_line_plot(figure.cr(), {0.0, half, double(width), half}, bottom);
  return figure;
}

}  // namespace rheomag::figures
