#pragma once
// A valve's pressure drop against flow rate at several currents, and its dynamic range.

#include "plot/figure.hpp"
#include "valve/valve_report.hpp"

namespace rheomag::figures {

/// Above: the field-integrated pressure drop dp [bar] against the flow rate Q [L/min], one
/// curve per current. Below: the dynamic range dp(largest current) / dp(smallest current)
/// against Q (when the report has two currents or more).
plot::Figure valve_curves_figure(const valve::ValveReport& report, int width, int height);

}  // namespace rheomag::figures
