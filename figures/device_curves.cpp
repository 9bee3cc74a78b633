#include "figures/device_curves.hpp"

#include <cmath>
#include <cstdio>

namespace rheomag::figures {

plot::LinePlot curves_per_current(const std::string& title, const std::string& x_label,
                                  const std::string& y_label, const std::vector<double>& current,
                                  const std::vector<double>& x, const std::vector<double>& y) {
  plot::LinePlot p;
  p.title = title;
  p.x_label = x_label;
  p.y_label = y_label;
  p.y_from_zero = true;
  for (std::size_t i = 0; i < current.size(); ++i) {
    if (i == 0 || current[i] != current[i - 1]) {
      char name[64];
      std::snprintf(name, sizeof name, "I = %g A", current[i]);
      p.series.push_back(
          {name, {}, {}, plot::series_colour(static_cast<int>(p.series.size())), false, true});
    }
    p.series.back().x.push_back(x[i]);
    p.series.back().y.push_back(y[i]);
  }
  return p;
}

plot::Figure damper_curves_figure(const valve::DamperReport& report, int width, int height) {
  std::vector<double> current, velocity, force;
  for (const valve::DamperPoint& p : report.points) {
    current.push_back(p.current);
    velocity.push_back(p.velocity);
    force.push_back(p.force);
  }
  return plot::line_plot_figure(
      curves_per_current(report.case_name + ": force-velocity (" + report.fluid + ")",
                         "piston velocity [m/s] (> 0 compression)", "force [N]", current, velocity,
                         force),
      width, height);
}

plot::Figure brake_curves_figure(const valve::BrakeReport& report, int width, int height) {
  constexpr double kRpmPerRadPerSecond = 60.0 / (2.0 * M_PI);
  std::vector<double> current, speed, torque;
  for (const valve::BrakePoint& p : report.points) {
    current.push_back(p.current);
    speed.push_back(kRpmPerRadPerSecond * p.speed);
    torque.push_back(p.torque.torque);
  }
  return plot::line_plot_figure(
      curves_per_current(report.case_name + ": torque-speed (" + report.fluid + ")", "speed [rpm]",
                         "torque [N m]", current, speed, torque),
      width, height);
}

}  // namespace rheomag::figures
