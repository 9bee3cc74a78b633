#include "magnetostatics/sweep_report.hpp"

#include "core/format_text.hpp"

namespace rheomag::magnetostatics {

nlohmann::json sweep_json(const std::vector<SweepPoint>& table) {
  nlohmann::json rows = nlohmann::json::array();
  for (const SweepPoint& p : table)
    rows.push_back({{"current", p.current},
                    {"flux_linkage", p.flux_linkage},
                    {"inductance", p.secant_inductance},
                    {"incremental_inductance", p.incremental_inductance},
                    {"newton_iterations", p.newton_iterations}});
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
  return out;
}

}  // namespace rheomag::magnetostatics
