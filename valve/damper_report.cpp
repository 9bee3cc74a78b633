#include "valve/damper_report.hpp"

#include <tuple>

#include "core/error.hpp"
#include "core/format_text.hpp"

namespace rheomag::valve {

DamperReport evaluate_damper(const cases::Case& c, const std::vector<double>& currents,
                             const std::vector<double>& velocities,
                             const ProgressCallback& progress) {
  const DamperOptions options = read_damper_options(c);
  const std::vector<double> at_currents = currents_or_case(c, currents);
  const std::vector<double> at_velocities = velocities.empty() ? options.velocities : velocities;
  if (at_velocities.empty())
    throw InputError(c.source.string() +
                     ": no velocity: pass --velocity V[,V...] (m/s) or set "
                     "[damper] velocity in the case");
  DamperChain chain(c, options);
  chain.set_progress(progress);
  DamperReport report;
  report.case_name = c.name;
  report.fluid = chain.fluid().name;
  report.gap_wall = options.gap_wall;
  report.points = chain.evaluate(at_currents, at_velocities);
  std::tie(report.gas_extended, report.gas_compressed) = gas_force_range(options);
  return report;
}

nlohmann::json damper_json(const DamperReport& report) {
  nlohmann::json out;
  out["case"] = report.case_name;
  out["fluid"] = report.fluid;
  out["gap_wall"] = std::string(kGapWallNames.name(report.gap_wall));
  out["gas_force_range"] = {report.gas_extended, report.gas_compressed};
  out["points"] = nlohmann::json::array();
  for (const auto& p : report.points) {
    nlohmann::json gaps = nlohmann::json::array();
    for (const auto& g : p.gaps)
      gaps.push_back({{"name", g.name},
                      {"b_average", g.drop.b_average},
                      {"dp", g.drop.dp},
                      {"dp_yield", g.drop.dp_yield},
                      {"dp_viscous", g.drop.dp_viscous},
                      {"wall_force", g.drop.wall_force},
                      {"regime", std::string(fluid::kMixedRegimeNames.name(g.drop.regime))},
                      {"plug_fraction", g.drop.plug_fraction}});
    out["points"].push_back({{"current", p.current},
                             {"velocity", p.velocity},
                             {"force", p.force},
                             {"force_pressure", p.force_pressure},
                             {"force_wall", p.force_wall},
                             {"force_gas", p.force_gas},
                             {"dp", p.dp},
                             {"dp_viscous", p.dp_viscous},
                             {"flow", p.flow},
                             {"wall_velocity", p.wall_velocity},
                             {"inductance", p.inductance},
                             {"gaps", gaps}});
  }
  return out;
}

std::string damper_text(const DamperReport& report) {
  std::string out = format_text(
      "damper %s, fluid %s, gap wall %s; gas force %.4g N (%.4g .. %.4g N over the "
      "stroke)\n",
      report.case_name.c_str(), report.fluid.c_str(),
      std::string(kGapWallNames.name(report.gap_wall)).c_str(), report.points.front().force_gas,
      report.gas_extended, report.gas_compressed);
  out += format_text("%8s %10s %12s %12s %12s %12s\n", "I [A]", "v [m/s]", "F [N]", "F_dp [N]",
                     "F_wall [N]", "dp [bar]");
  for (const auto& p : report.points)
    out += format_text("%8.4g %10.4g %12.5g %12.5g %12.5g %12.5g\n", p.current, p.velocity, p.force,
                       p.force_pressure, p.force_wall, p.dp * 1e-5);
  return out;
}

}  // namespace rheomag::valve
