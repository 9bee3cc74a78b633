#include "figures/device_sections.hpp"

#include <algorithm>

#include "figures/valve_curves.hpp"
#include "valve/valve_options.hpp"
#include "valve/valve_report.hpp"

namespace rheomag::figures {

std::vector<ReportSection> device_sections(const cases::Case& c, double current) {
  std::vector<ReportSection> sections;
  bool has_gap = false;
  for (const mesh::RegionSeed& region : c.problem.geometry.regions)
    has_gap = has_gap || region.gap != mesh::GapKind::none;
  if (c.fluid.empty() || !has_gap || c.problem.circuits.empty()) return sections;
  const valve::ValveOptions options = valve::read_valve_options(c);
  if (options.flows.empty()) return sections;
  const double design_flow = *std::max_element(options.flows.begin(), options.flows.end());
  std::vector<double> flows;
  for (int k = 0; k < 10; ++k) flows.push_back(design_flow * (0.1 + 1.9 * k / 9.0));
  const double on = current != 0.0 ? current : 1.0;
  const valve::ValveReport report =
      valve::evaluate_valve(c, options, {0.0, 0.5 * on, on, 1.5 * on}, flows);
  sections.push_back({"Pressure drop against flow",
                      "The valve chain (" + report.fluid +
                          ", the gaps in series, B(s) along each gap) at four currents, and the "
                          "dynamic range dp(largest current) / dp(0 A).",
                      valve_curves_figure(report, 900, 800)});
  return sections;
}

}  // namespace rheomag::figures
