// Valve chain: every fluid gap region of the case (RegionSeed::gap annular or radial) is a
// segment in series (the flow passes each gap once; paper 000's valve: the two pole gaps); the
// per-field evaluation is SolvedValve (solved_valve.cpp). Coil: turns and the winding window
// (area, area-weighted mean radius) from the coil regions of the mesh (coil_spec); resistance
// etc. from coil.cpp.

#include "valve/valve_chain.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "case/toml_section.hpp"
#include "core/error.hpp"
#include "valve/field_solve.hpp"
#include "valve/solved_valve.hpp"

namespace rheomag::valve {

ValveOptions read_valve_options(const cases::Case& c) {
  ValveOptions options;
  const cases::TomlSection top(c.table, "", c.source.string());
  // A template case winding its coil from [geometry] wire + fill_factor has its wire there.
  options.wire = c.input.winding.wire;
  options.wire_diameter = c.input.winding.wire_diameter;
  auto valve = top.table("valve");
  if (!valve) return options;
  valve->allow_only({"wire", "temperature", "inlet_radius", "flow", "passage", "loss"});
  options.passages = fluid::read_passages(*valve);
  options.losses = fluid::read_losses(*valve);
  if (auto wire = valve->string("wire")) {
    double diameter = 0.0;
    try {
      diameter = wire_diameter(*wire);
    } catch (const InputError& e) {
      valve->fail("wire", e.what());
    }
    if (!options.wire.empty() && diameter != options.wire_diameter)
      valve->fail("wire", "\"" + *wire + "\" differs from [geometry] wire = \"" + options.wire +
                              "\"; give the wire once");
    options.wire = *wire;
    options.wire_diameter = diameter;
  }
  options.temperature = valve->number_or("temperature", 20.0);
  options.inlet_radius = valve->non_negative_or("inlet_radius", 0.0);
  if (auto flow = valve->number("flow")) {
    if (!(*flow > 0.0)) throw InputError(c.source.string() + ": [valve].flow must be > 0 m^3/s");
    options.flows = {*flow};
  }
  return options;
}

ValveChain::ValveChain(const cases::Case& c, ValveOptions options) : options_(std::move(options)) {
  const std::string where = c.source.string();
  fluid_ = case_fluid(c);
  if (c.problem.circuits.empty()) throw InputError(where + ": the case has no coil circuit");
  if (std::none_of(c.problem.geometry.regions.begin(), c.problem.geometry.regions.end(),
                   [](const mesh::RegionSeed& r) { return r.gap != mesh::GapKind::none; }))
    throw InputError(where + ": the case has no fluid gap");
  solver_ = make_device_solver(c);
  coil_ = coil_spec(*solver_, options_);
}

std::vector<ValvePoint> ValveChain::evaluate(const std::vector<double>& currents,
                                             const std::vector<double>& flows) {
  if (currents.empty() || flows.empty())
    throw InputError("valve: needs at least one current and one flow rate");
  for (double flow : flows)
    if (!(std::isfinite(flow) && flow > 0.0))
      throw InputError("valve: flow rates must be > 0 m^3/s");
  std::vector<ValvePoint> points;
  for (double current : currents) {
    const DeviceField field = solve_at_current(*solver_, current);
    const SolvedValve valve(*solver_, field.solution, field.results, fluid_, options_);
    for (double flow : flows) points.push_back(valve.point(flow));
  }
  return points;
}

CoilProperties ValveChain::coil(double current, double inductance) const {
  if (options_.wire.empty())
    throw InputError(
        "valve: the coil resistance needs the wire: set [valve] wire = \"AWG 24\" (or \"0.5 mm\") "
        "in the case or pass --wire");
  return coil_properties(coil_, current, inductance);
}

}  // namespace rheomag::valve
