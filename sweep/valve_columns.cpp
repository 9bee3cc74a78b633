#include "sweep/valve_columns.hpp"

#include "valve/solved_valve.hpp"
#include "valve/valve_chain.hpp"

namespace rheomag::sweep {

namespace {

double first_current(const SolvedDesign& solved) {
  return solved.results.circuits.empty() ? 0.0 : solved.results.circuits.front().current;
}

double first_inductance(const SolvedDesign& solved) {
  return solved.results.circuits.empty() ? 0.0 : solved.results.circuits.front().inductance;
}

}  // namespace

std::vector<ColumnGroup> valve_columns(const SweepSpec& spec) {
  if (!spec.base.table.contains("valve")) return {};
  const valve::ValveOptions base = valve::read_valve_options(spec.base);
  const bool pressure = !base.flows.empty();
  const bool coil = !base.wire.empty();
  if (!pressure && !coil) return {};
  ColumnGroup group;
  if (pressure) {
    group.names = {"dp_total_Pa", "dp_yield_Pa", "dp_viscous_Pa", "dp_total_average_b_Pa"};
  }
  if (coil) {
    group.names.insert(group.names.end(),
                       {"coil_resistance_Ohm", "coil_time_constant_s", "coil_power_W"});
  }
  group.evaluate = [pressure, coil](const SolvedDesign& solved) {
    // The design's own field solve (no second mesh or solve).
    const cases::Case& c = solved.design_case;
    const valve::ValveOptions options = valve::read_valve_options(c);
    std::vector<double> values;
    if (pressure) {
      const valve::SolvedValve valve(solved.solver, solved.solution, solved.results,
                                     valve::case_fluid(c), options);
      const valve::ValvePoint point = valve.point(options.flows.front());
      values.insert(values.end(),
                    {point.dp_total, point.dp_yield, point.dp_viscous, point.dp_total_average_b});
    }
    if (coil) {
      const valve::CoilProperties properties =
          valve::coil_properties(valve::coil_spec(solved.solver, options), first_current(solved),
                                 first_inductance(solved));
      values.insert(values.end(),
                    {properties.resistance, properties.time_constant, properties.power});
    }
    return values;
  };
  return {group};
}

}  // namespace rheomag::sweep
