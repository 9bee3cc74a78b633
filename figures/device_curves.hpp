#pragma once
// Curves of a device's output against its operating variable, one per current: a damper's
// force against velocity, a brake's torque against speed.

#include <string>
#include <vector>

#include "plot/line_plot.hpp"
#include "valve/brake_report.hpp"
#include "valve/damper_report.hpp"

namespace rheomag::figures {

/// The line plot of points (current[i], x[i], y[i]) listed current-major: one curve (with
/// markers) per run of equal currents, named "I = ... A".
plot::LinePlot curves_per_current(const std::string& title, const std::string& x_label,
                                  const std::string& y_label, const std::vector<double>& current,
                                  const std::vector<double>& x, const std::vector<double>& y);

/// Force [N] against piston velocity [m/s], one curve per current.
plot::Figure damper_curves_figure(const valve::DamperReport& report, int width, int height);

/// Torque [N m] against speed [rpm], one curve per current.
plot::Figure brake_curves_figure(const valve::BrakeReport& report, int width, int height);

}  // namespace rheomag::figures
