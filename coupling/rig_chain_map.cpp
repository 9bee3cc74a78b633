// Tabulation of a rig's FE valve map over its drive's current and flow range.

#include "coupling/rig_chain_map.hpp"

#include <algorithm>
#include <cmath>

#include "coupling/valve_chain_tabulation.hpp"

namespace rheomag::coupling {

lumped::RigSpec with_chain_map(const lumped::RigSpec& spec, const lumped::Recording& drive) {
  lumped::RigSpec s = spec;
  if (s.valve.case_file.empty() || s.valve.chain || s.kind == lumped::RigKind::coil_bench) return s;
  double i_max = 0.0, q_max = 0.0;
  auto largest = [](const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
  };
  if (s.driver_mode == lumped::DriverMode::current_source)
    i_max = largest(drive.column("current"));
  else if (s.driver_mode == lumped::DriverMode::current_pi)
    i_max = largest(drive.column("current_cmd"));
  else
    i_max = s.driver.gain * largest(drive.column(s.voltage_column)) / s.coil.resistance_20c;
  q_max = s.piston_area * largest(drive.column("velocity"));
  if (!(q_max > 0.0)) q_max = 1e-6;
  s.valve.chain = tabulate_valve_chain(s.valve.case_file, i_max > 0.0 ? 1.05 * i_max : 1.0, q_max);
  return s;
}

}  // namespace rheomag::coupling
