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

ValveChain::ValveChain(const cases::Case& c, ValveOptions options)
    : DeviceChain(c, "valve", std::move(options)) {
  if (std::none_of(c.problem.geometry.regions.begin(), c.problem.geometry.regions.end(),
                   [](const mesh::RegionSeed& r) { return r.gap != mesh::GapKind::none; }))
    throw InputError(c.source.string() + ": the case has no fluid gap");
}

std::vector<ValvePoint> ValveChain::evaluate(const std::vector<double>& currents,
                                             const std::vector<double>& flows) {
  for (double flow : flows)
    if (!(std::isfinite(flow) && flow > 0.0))
      throw InputError("valve: flow rates must be > 0 m^3/s");
  return per_current<ValvePoint>(currents, flows.size(), "flow rate",
                                 [&](const magnetostatics::MagnetostaticSolver& solver,
                                     const DeviceField& field, const PointDone& point_done) {
                                   const SolvedValve valve(solver, field.solution, field.results,
                                                           fluid_, valve_options_);
                                   std::vector<ValvePoint> points;
                                   for (double flow : flows) {
                                     points.push_back(valve.point(flow));
                                     point_done();
                                   }
                                   return points;
                                 });
}

}  // namespace rheomag::valve
