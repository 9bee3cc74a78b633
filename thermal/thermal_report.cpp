// `rheomag thermal`: set-up of the thermal model of a device case, its steady or transient run,
// and the text, JSON and VTK outputs.

#include "thermal/thermal_report.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "core/format_text.hpp"
#include "mesh/vtu_writer.hpp"
#include "thermal/model_from_case.hpp"
#include "thermal/thermal_spec.hpp"

namespace rheomag::thermal {

std::string motion_name(Motion motion) {
  switch (motion) {
    case Motion::none:
      return "none";
    case Motion::flow:
      return "flow";
    case Motion::velocity:
      return "velocity";
    case Motion::speed:
      return "speed";
  }
  return "none";
}

namespace {

/// The unit of the operating point's value and of the device's output.
const char* value_unit(Motion m) {
  return m == Motion::flow ? "m^3/s" : m == Motion::velocity ? "m/s" : "rad/s";
}
const char* output_name(Motion m) {
  return m == Motion::flow ? "pressure drop" : m == Motion::velocity ? "force" : "torque";
}
const char* output_unit(Motion m) {
  return m == Motion::flow ? "Pa" : m == Motion::velocity ? "N" : "N m";
}

/// A finite number for JSON, null otherwise.
nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

/// A valve's flow carries heat out of its gaps: all gaps as one well-mixed volume V, the fluid
/// entering at `inlet`, beta = rho c_p Q / V (ThroughFlow in docs/thermal.md).
void add_through_flow(HeatModel& model, const DeviceHeatModel& device, double flow, double inlet) {
  const cases::Problem& problem = device.solver().problem();
  double gaps = 0.0;
  for (int r : device.gap_regions()) gaps += device.region_volume()[r];
  const cases::Material& fluid =
      problem.materials[problem.regions[device.gap_regions().front()].material];
  if (!fluid.thermal)
    throw InputError("thermal: the fluid '" + fluid.name + "' has no thermal data");
  for (int r : device.gap_regions()) {
    model.regions[r].exchange = fluid.thermal->heat_capacity() * std::abs(flow) / gaps;
    model.regions[r].exchange_temperature = inlet;
  }
}

}  // namespace

ThermalReport run_thermal(const cases::Case& c, const ThermalRequest& request) {
  ThermalSpec spec = read_thermal_spec(c);
  if (request.ambient) spec.ambient = *request.ambient;
  if (request.convection) {
    if (!(*request.convection >= 0.0) || !std::isfinite(*request.convection))
      throw InputError(format_text("--convection: expected a coefficient >= 0 W/(m^2 K), got %.6g",
                                   *request.convection));
    spec.convection = *request.convection;
  }
  if (request.limit) spec.limit = request.limit;
  DeviceHeatModel device(c, request.point);
  const magnetostatics::MagnetostaticSolver& field = device.solver();
  const double fill = spec.copper_fill.value_or(device.copper_fill());
  HeatModel model = build_heat_model(field.problem(), spec, fill);
  if (request.point.motion == Motion::flow)
    add_through_flow(model, device, request.point.value, spec.ambient);
  HeatSolver solver(field.problem(), field.mesh(), std::move(model));
  CouplingOptions coupling;
  coupling.temperature = request.temperature;
  ThermalReport report;
  report.case_name = c.name;
  report.point = request.point;
  report.ambient = spec.ambient;
  report.limit = spec.limit;
  report.copper_fill = fill;
  report.unknowns = solver.unknowns();
  if (request.duration) {
    report.transient = transient_device(device, solver, coupling, spec.ambient, *request.duration,
                                        request.steps, spec.limit);
    report.field = report.transient->last;
  } else {
    report.steady = steady_device(device, solver, coupling, spec.ambient);
    report.field = report.steady.solution;
  }
  if (!device.coil_regions().empty() && !device.gap_regions().empty())
    report.network =
        fit_network(solver, device.coil_regions(), device.gap_regions(), device.region_volume());
  const cases::Problem& problem = field.problem();
  for (std::size_t r = 0; r < problem.regions.size(); ++r) {
    const HeatRegion& data = solver.model().regions[r];
    RegionReport region;
    region.name = problem.geometry.regions[r].name;
    region.active = data.active;
    region.conductivity = data.conductivity;
    region.heat_capacity = data.heat_capacity;
    region.temperature = report.field.regions[r];
    region.volume = region.temperature.volume;
    region.power = data.source * region.volume;
    report.regions.push_back(region);
    report.region_names.push_back(region.name);
  }
  report.surfaces = solver.model().surfaces;
  report.surface_heat_flow = report.field.surface_heat_flow;
  report.balance_error = report.field.balance_error();
  report.mesh = field.mesh();
  report.planar = problem.symmetry == cases::Symmetry::planar;
  return report;
}

std::string thermal_text(const ThermalReport& r) {
  std::ostringstream out;
  const OperatingPoint& p = r.point;
  out << "case: " << r.case_name << "\n";
  out << format_text("operating point: %.6g A", p.current);
  if (p.motion != Motion::none)
    out << format_text(", %s %.6g %s", motion_name(p.motion).c_str(), p.value,
                       value_unit(p.motion));
  out << format_text(", duty %.3g; ambient %.4g C\n", p.duty, r.ambient);
  const auto temps = [&](const DeviceTemperatures& t) {
    out << format_text("  coil:  mean %8.2f C   max %8.2f C\n", t.coil_mean, t.coil_max);
    if (std::isfinite(t.fluid_mean))
      out << format_text("  fluid: mean %8.2f C   max %8.2f C (the gaps)\n", t.fluid_mean,
                         t.fluid_max);
  };
  if (r.transient) {
    const DeviceTransient& t = *r.transient;
    out << format_text("transient from %.4g C over %.6g s (%zu steps):\n", r.ambient,
                       t.samples.back().time, t.samples.size() - 1);
    out << "   time [s]   coil mean   coil max   fluid mean   fluid max   coil W   fluid W\n";
    const std::size_t stride = std::max<std::size_t>(1, (t.samples.size() - 1) / 10);
    for (std::size_t i = 0; i < t.samples.size(); i += stride) {
      const DeviceSample& s = t.samples[i];
      out << format_text("  %9.4g  %10.2f %10.2f  %11.2f %11.2f %8.3g %9.3g\n", s.time,
                         s.temperatures.coil_mean, s.temperatures.coil_max,
                         s.temperatures.fluid_mean, s.temperatures.fluid_max, s.coil_power,
                         s.fluid_power);
    }
    if (!t.stopped.empty())
      out << format_text("stopped at %.6g s: %s\n", t.samples.back().time, t.stopped.c_str());
    out << "at the end:\n";
    temps(t.samples.back().temperatures);
    if (r.limit)
      out << (t.time_to_limit
                  ? format_text("time to reach %.4g C: %.4g s\n", *r.limit, *t.time_to_limit)
                  : format_text("the limit %.4g C is not reached in %.6g s\n", *r.limit,
                                t.samples.back().time));
  } else {
    const SteadyDevice& s = r.steady;
    out << (s.coupled ? format_text("steady state (coupled: %d thermal solves to settle the "
                                    "fluid's and the coil's temperatures):\n",
                                    s.iterations)
                      : "steady state, the chain at the given temperature:\n");
    temps(s.temperatures);
    out << format_text("heat: coil %.4g W (R = %.4g Ohm), fluid %.4g W\n", s.heat.coil_power,
                       s.heat.coil_resistance, s.heat.fluid_power);
    if (p.motion != Motion::none)
      out << format_text("%s at this temperature: %.6g %s\n", output_name(p.motion), s.heat.output,
                         output_unit(p.motion));
    if (r.limit)
      out << format_text("limit %.4g C: %s (hottest %.2f C)\n", *r.limit,
                         s.temperatures.hottest() <= *r.limit ? "within" : "EXCEEDED",
                         s.temperatures.hottest());
  }
  out << "heat leaving through the surfaces:\n";
  for (std::size_t i = 0; i < r.surfaces.size(); ++i)
    out << format_text("  %-20s %-12s %10.4g W\n", r.surfaces[i].name.c_str(),
                       std::string(kSurfaceKindNames.name(r.surfaces[i].kind)).c_str(),
                       r.surface_heat_flow[i]);
  if (r.field.exchange_heat_flow != 0.0)
    out << format_text(
        "  %-20s %-12s %10.4g W (the gaps as one mixed volume, inflow at "
        "ambient)\n",
        "fluid through-flow", "advection", r.field.exchange_heat_flow);
  out << format_text("energy balance: %.2g of the sources (copper fill %.3f, %d unknowns)\n",
                     r.balance_error, r.copper_fill, r.unknowns);
  if (r.network) {
    const ThermalNetwork& n = *r.network;
    const Eigen::Vector2d tau = n.time_constants();
    out << format_text(
        "two-node network (coil, fluid+body): C = %.4g, %.4g J/K; R = [%.4g %.4g; "
        "%.4g %.4g] K/W; time constants %.4g s, %.4g s\n",
        n.capacity[0], n.capacity[1], n.resistance(0, 0), n.resistance(0, 1), n.resistance(1, 0),
        n.resistance(1, 1), tau[0], tau[1]);
  }
  std::string outside;
  for (const RegionReport& region : r.regions)
    if (!region.active) outside += (outside.empty() ? "" : ", ") + region.name;
  if (!outside.empty()) out << "outside the thermal model (no thermal data): " << outside << "\n";
  return out.str();
}

nlohmann::json thermal_json(const ThermalReport& r) {
  nlohmann::json j;
  j["case"] = r.case_name;
  j["operating_point"] = {{"current", r.point.current},
                          {"motion", motion_name(r.point.motion)},
                          {"value", r.point.value},
                          {"duty", r.point.duty}};
  j["ambient"] = r.ambient;
  j["limit"] = r.limit ? nlohmann::json(*r.limit) : nlohmann::json();
  j["copper_fill"] = r.copper_fill;
  j["unknowns"] = r.unknowns;
  const auto temps = [](const DeviceTemperatures& t) {
    return nlohmann::json{{"coil_mean", number(t.coil_mean)},
                          {"coil_max", number(t.coil_max)},
                          {"fluid_mean", number(t.fluid_mean)},
                          {"fluid_max", number(t.fluid_max)}};
  };
  if (r.transient) {
    nlohmann::json samples = nlohmann::json::array();
    for (const DeviceSample& s : r.transient->samples) {
      nlohmann::json one = temps(s.temperatures);
      one["time"] = s.time;
      one["coil_power"] = number(s.coil_power);
      one["fluid_power"] = number(s.fluid_power);
      samples.push_back(one);
    }
    j["transient"] = {
        {"duration", r.transient->samples.back().time},
        {"steps", r.transient->samples.size() - 1},
        {"time_to_limit", r.transient->time_to_limit ? nlohmann::json(*r.transient->time_to_limit)
                                                     : nlohmann::json()},
        {"samples", samples},
        {"stopped",
         r.transient->stopped.empty() ? nlohmann::json() : nlohmann::json(r.transient->stopped)}};
    j["temperatures"] = temps(r.transient->samples.back().temperatures);
  } else {
    const SteadyDevice& s = r.steady;
    j["coupled"] = s.coupled;
    j["iterations"] = s.iterations;
    j["temperatures"] = temps(s.temperatures);
    j["coil_resistance"] = s.heat.coil_resistance;
    j["coil_power"] = s.heat.coil_power;
    j["fluid_power"] = s.heat.fluid_power;
    if (r.point.motion != Motion::none) j["output"] = s.heat.output;
    if (r.limit) j["within_limit"] = s.temperatures.hottest() <= *r.limit;
  }
  nlohmann::json surfaces = nlohmann::json::array();
  for (std::size_t i = 0; i < r.surfaces.size(); ++i)
    surfaces.push_back({{"name", r.surfaces[i].name},
                        {"kind", std::string(kSurfaceKindNames.name(r.surfaces[i].kind))},
                        {"heat_flow", r.surface_heat_flow[i]}});
  j["surfaces"] = surfaces;
  j["through_flow_heat"] = r.field.exchange_heat_flow;
  j["balance_error"] = r.balance_error;
  nlohmann::json regions = nlohmann::json::array();
  for (const RegionReport& region : r.regions) {
    nlohmann::json one{{"name", region.name}, {"in_model", region.active}};
    if (region.active) {
      one["conductivity"] = region.conductivity;
      one["heat_capacity"] = region.heat_capacity;
      one["volume"] = region.volume;
      one["power"] = region.power;
      one["mean"] = region.temperature.mean;
      one["max"] = region.temperature.max;
    }
    regions.push_back(one);
  }
  j["regions"] = regions;
  if (r.network) {
    const ThermalNetwork& n = *r.network;
    const Eigen::Vector2d tau = n.time_constants();
    j["network"] = {
        {"capacity", {n.capacity[0], n.capacity[1]}},
        {"resistance",
         {{n.resistance(0, 0), n.resistance(0, 1)}, {n.resistance(1, 0), n.resistance(1, 1)}}},
        {"baseline", {n.baseline[0], n.baseline[1]}},
        {"time_constants", {tau[0], tau[1]}}};
  }
  return j;
}

void write_thermal_vtu(const ThermalReport& r, const std::string& path) {
  // Only the thermal model's triangles: the surroundings have no temperature.
  mesh::VtuGrid grid;
  const int per = r.mesh.nodes_per_triangle();
  grid.cell_type = per == 3 ? 5 : 22;  // VTK_TRIANGLE, VTK_QUADRATIC_TRIANGLE (mesh.hpp order)
  grid.nodes_per_cell = per;
  std::vector<int> point_of_node(r.mesh.nodes.size(), -1);
  std::vector<double> temperature, source;
  for (std::size_t e = 0; e < r.mesh.triangles.size(); ++e) {
    const RegionReport& region = r.regions[r.mesh.region[e]];
    if (!region.active) continue;
    for (int i = 0; i < per; ++i) {
      const int node = r.mesh.triangles[e][i];
      if (point_of_node[node] < 0) {
        point_of_node[node] = static_cast<int>(grid.points.size());
        grid.points.push_back({r.mesh.nodes[node].r, r.mesh.nodes[node].z, 0.0});
        temperature.push_back(r.field.temperature[node]);
      }
      grid.connectivity.push_back(point_of_node[node]);
    }
    grid.region.push_back(r.mesh.region[e]);
    source.push_back(region.volume > 0.0 ? region.power / region.volume : 0.0);
  }
  mesh::VtuFields fields;
  fields.add_point_scalar("temperature", std::move(temperature));
  fields.add_cell_scalar("heat_source", std::move(source));
  mesh::write_vtu(path, grid, fields, r.region_names);
}

}  // namespace rheomag::thermal
