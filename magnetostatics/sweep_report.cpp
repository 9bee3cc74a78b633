#include "magnetostatics/sweep_report.hpp"

#include "core/format_text.hpp"

namespace rheomag::magnetostatics {

nlohmann::json sweep_json(const std::vector<SweepPoint>& table) {
  nlohmann::json rows = nlohmann::json::array();
  for (const SweepPoint& p : table) {
    nlohmann::json gaps = nlohmann::json::array();
    for (const SweepGap& g : p.gaps)
      gaps.push_back({{"name", g.name},
                      {"B_avg", g.b_avg},
                      {"B_max_midline", g.b_max_midline},
                      {"B_max_area", g.b_max_area}});
    rows.push_back({{"current", p.current},
                    {"flux_linkage", p.flux_linkage},
                    {"inductance", p.secant_inductance},
                    {"incremental_inductance", p.incremental_inductance},
                    {"newton_iterations", p.newton_iterations},
                    {"gaps", gaps}});
  }
  return rows;
}

std::string sweep_text(const std::vector<SweepPoint>& table, const std::string& circuit) {
  if (table.empty()) return {};
  std::string out = "\nlambda(I) table of circuit " + circuit +
                    "\n  current [A]  lambda [mWb]  L=lambda/I [mH]  dlambda/dI [mH]  Newton\n";
  for (const SweepPoint& p : table)
    out +=
        format_text("  %11.4g %13.5g %16.5g %16.5g %7d\n", p.current, p.flux_linkage * 1e3,
                    p.secant_inductance * 1e3, p.incremental_inductance * 1e3, p.newton_iterations);
  if (table.front().gaps.empty()) return out;
  out +=
      "\ngap flux density against current (docs/quantities.md)\n  current [A]  gap                 "
      "  "
      "B_avg [T]  B_max_midline [T]  B_max_area [T]\n";
  for (const SweepPoint& p : table)
    for (const SweepGap& g : p.gaps)
      out += format_text("  %11.4g  %-20.20s %10.3f %18.3f %15.3f\n", p.current, g.name.c_str(),
                         g.b_avg, g.b_max_midline, g.b_max_area);
  return out;
}

}  // namespace rheomag::magnetostatics
