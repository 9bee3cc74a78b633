// Gap pressure drops from valve::SolvedValve (the valve chain on the already solved field: every
// gap in series, local tau_y(B(s)) along each mid-line; off state: B = 0). Coil: valve::coil_spec
// (turns and winding window from the circuit-0 regions of the (morphed) mesh).

#include "optimise/evaluate.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <numbers>

#include "case/wire_gauge.hpp"
#include "core/error.hpp"
#include "design/response_time.hpp"
#include "mesh/triangle.hpp"
#include "thermal/design_temperature.hpp"
#include "valve/coil.hpp"
#include "valve/solved_valve.hpp"

namespace rheomag::optimise {

namespace {

constexpr int kRiseSamples = 4;  // lambda(i) samples of the rise-time integral
// Most memory the quasi-static table's kept factorisations take (for linearised neighbours; the
// P2 response-time example's peak memory grew by 134 MB with them, docs/performance.md, round 9).
constexpr std::size_t kNeighbourFactorBytes = std::size_t{512} << 20;

// 90 % rise time of the coil current after a voltage step V on R and the flux linkage
// lambda(i): V = R i + dlambda/dt, so t = integral_0^{0.9 I_f} lambda'(i) / (V - R i) di with
// I_f = V / R. lambda(i) is taken piecewise linear through (0, 0) and the samples (i_k,
// lambda_k), on which the integral is exact: sum_k L_k / R ln((I_f - i_{k-1}) / (I_f - i_k)).
double rise_time_90(const std::vector<double>& current, const std::vector<double>& flux,
                    double resistance, double final_current) {
  double t = 0.0, i_prev = 0.0, flux_prev = 0.0;
  for (std::size_t k = 0; k < current.size(); ++k) {
    const double slope = (flux[k] - flux_prev) / (current[k] - i_prev);
    t += slope / resistance * std::log((final_current - i_prev) / (final_current - current[k]));
    i_prev = current[k];
    flux_prev = flux[k];
  }
  return t;
}

}  // namespace

OptimiseEvaluator::OptimiseEvaluator(cases::Case base, OptimiseSpec spec)
    : base_(std::move(base)), spec_(std::move(spec)), designs_(design::MeshPolicy::morphed, [] {
        magnetostatics::SolveOptions options;
        options.incremental_inductance = false;
        return options;
      }()) {
  const std::string where = base_.source.string();
  for (std::size_t i = 0; i < spec_.variables.size(); ++i) {
    const cases::CaseKey& key = spec_.variables[i].target;
    if (key.target == cases::KeyTarget::wire_gauge) gauge_index_ = static_cast<int>(i);
    if (!key.path.empty() && key.path.front() == "valve") valve_varies_ = true;
    if (key.target == cases::KeyTarget::circuit_current && key.circuit == 0) current_varies_ = true;
  }
  fluid_ = valve::case_fluid(base_);
  if (base_.problem.circuits.empty()) throw InputError(where + ": the case has no coil circuit");
  valve_ = valve::read_valve_options(base_);
  static const std::vector<design::Quantity> needs_wire = {design::Quantity::resistance,
                                                           design::Quantity::time_constant,
                                                           design::Quantity::power,
                                                           design::Quantity::current_density,
                                                           design::Quantity::copper_fill,
                                                           design::Quantity::temperature_rise,
                                                           design::Quantity::rise_time,
                                                           design::Quantity::response_time,
                                                           design::Quantity::coil_temperature,
                                                           design::Quantity::fluid_temperature};
  for (design::Quantity q : needs_wire)
    if (valve_.wire.empty() && uses(spec_, q))
      throw InputError(where + ": \"" + design::quantity_name(q) +
                       "\" needs the coil wire: set [valve] wire = \"AWG 24\" (or \"0.5 mm\")");
  if (spec_.velocity != 0.0) damper_ = valve::read_damper_options(base_);
  if (spec_.speed != 0.0) brake_ = valve::read_brake_options(base_);
  for (const auto& [name, density] : spec_.densities) {
    const auto& materials = base_.problem.materials;
    const auto used = std::find_if(materials.begin(), materials.end(),
                                   [&](const auto& m) { return m.name == name; });
    if (used == materials.end()) {
      std::string known;
      for (const auto& m : materials) known += (known.empty() ? "\"" : ", \"") + m.name + "\"";
      throw InputError(where + ": [optimise.density] names \"" + name +
                       "\", which is no material of the case (expected one of " + known + ")");
    }
  }
  if (uses(spec_, design::Quantity::mass) || uses(spec_, design::Quantity::torque_per_mass)) {
    if (base_.problem.symmetry != cases::Symmetry::axisymmetric)
      throw InputError(where + ": \"mass\" needs an axisymmetric case");
    const auto& regions = base_.problem.regions;
    for (std::size_t k = 0; k < regions.size(); ++k) {
      const std::string& name = base_.problem.materials.at(regions[k].material).name;
      const auto given = spec_.densities.find(name);
      if (static_cast<int>(k) == base_.problem.geometry.default_region)
        region_density_.push_back(0.0);  // the surroundings (faces no region seed reaches)
      else if (given != spec_.densities.end())
        region_density_.push_back(given->second);
      else if (name == fluid_.name)
        region_density_.push_back(fluid_.density);
      else
        throw InputError(where + ": \"mass\" needs the density of \"" + name +
                         "\": add it to [optimise.density] (\"" + name + "\" = kg/m^3)");
    }
  }
  if (uses(spec_, design::Quantity::min_wall) && base_.input.valve &&
      base_.input.valve->walls().empty())
    throw InputError(where + ": the template " + base_.geometry_template + " declares no walls");
  if (uses(spec_, design::Quantity::min_wall) && !base_.input.valve)
    throw InputError(where +
                     ": \"min_wall\" needs a parametric template (annular_valve, "
                     "radial_valve, meandering_valve); this case has none");
}

cases::Case OptimiseEvaluator::case_at(const std::vector<double>& x) const {
  std::vector<cases::CaseEdit> edits;
  for (std::size_t i = 0; i < x.size(); ++i) edits.push_back({spec_.variables[i].target, x[i]});
  return cases::with(base_, edits);
}

design::Quantities OptimiseEvaluator::evaluate(const std::vector<double>& x, bool neighbour) {
  const cases::Case c = case_at(x);
  design::ProblemAdjustment relax;
  if (gauge_index_ >= 0 && !exact_winding_) {
    // Continuous relaxation: turns = fill A_window / (pi d(n)^2 / 4) without the case's floor,
    // so the turns (and everything after) are smooth in the gauge and the window.
    const double fill = c.input.winding.fill_factor;
    const double d = cases::awg_diameter_relaxed(x[static_cast<std::size_t>(gauge_index_)]);
    relax = [fill, d](cases::Problem& closed, const mesh::Mesh& mesh) {
      std::vector<double> window(closed.regions.size(), 0.0);
      for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        const auto& t = mesh.triangles[e];
        const mesh::Point a = mesh.nodes[t[0]], b = mesh.nodes[t[1]], p = mesh.nodes[t[2]];
        window[mesh.region[e]] += mesh::triangle_area(a, b, p);
      }
      for (std::size_t k = 0; k < closed.regions.size(); ++k)
        if (closed.regions[k].circuit >= 0 && closed.regions[k].turns != 0.0)
          closed.regions[k].turns = std::copysign(
              fill * window[k] / (0.25 * std::numbers::pi * d * d), closed.regions[k].turns);
    };
  }
  std::vector<double> currents(c.problem.circuits.size(), 0.0);
  for (std::size_t k = 1; k < currents.size(); ++k) currents[k] = c.problem.circuits[k].current;
  // The on-state current: [optimise] current, or the design's own when it is a variable.
  const double on_current = current_varies_ ? c.problem.circuits[0].current : spec_.current;
  currents[0] = on_current;
  // A finite-difference neighbour's Newton starts from its centre's on-state field (same mesh
  // topology; the centre itself from A = 0, so its values do not depend on the path).
  const long long meshes_before = designs_.meshes_built();
  const design::EvaluatedField& field =
      designs_.solve(c, currents, false, relax,
                     neighbour && centre_meshes_ == meshes_before ? &centre_field_ : nullptr);
  if (!neighbour) centre_field_ = field.solution.a, centre_meshes_ = designs_.meshes_built();
  const magnetostatics::MagnetostaticSolver& solver = *field.solver;
  const magnetostatics::Results& results = field.results;
  if (results.gaps.empty()) throw InputError(base_.source.string() + ": the case has no fluid gap");

  design::Quantities q;
  double fluid_power = 0.0;  // dissipated in the gaps at the operating point [W]
  valve::ValveOptions valve = valve_varies_ ? valve::read_valve_options(c) : valve_;
  if (gauge_index_ >= 0) {  // the design's own wire (typed, as the case holds it)
    valve.wire = c.input.winding.wire;
    valve.wire_diameter = c.input.winding.wire_diameter;
  }
  const valve::SolvedValve solved(solver, field.solution, results, fluid_, valve);
  if (spec_.flow > 0.0) {
    q[design::Quantity::dp_on] = solved.point(spec_.flow).dp_total;
    q[design::Quantity::dp_off] = solved.zero_field_point(spec_.flow).dp_total;
    q[design::Quantity::dynamic_range] = q[design::Quantity::dp_on] / q[design::Quantity::dp_off];
    fluid_power = q[design::Quantity::dp_on] * spec_.flow;
  }
  q[design::Quantity::b_gap] = solved.b_average();
  q[design::Quantity::min_gap] = solved.min_clearance();
  const double inductance = results.circuits.front().inductance;
  q[design::Quantity::inductance] = inductance;
  if (damper_) {
    const valve::SolvedDamper damper(solver, field.solution, results, fluid_, *damper_);
    const valve::DamperPoint on = damper.point(spec_.velocity);
    const valve::DamperPoint off = damper.zero_field().point(spec_.velocity);
    q[design::Quantity::force_on] = on.force;
    q[design::Quantity::force_off] = off.force;
    q[design::Quantity::force_range] = (on.force - on.force_gas) / (off.force - off.force_gas);
    fluid_power = (on.force - on.force_gas) * on.velocity;
  }
  if (brake_) {
    const valve::SolvedBrake brake(solver, field.solution, results, fluid_, *brake_);
    q[design::Quantity::torque_on] = brake.point(spec_.speed).torque.torque;
    fluid_power = q[design::Quantity::torque_on] * spec_.speed;
    q[design::Quantity::torque_off] = brake.zero_field().point(spec_.speed).torque.torque;
  }

  // Peak |B| over the elements of nonlinear (steel) materials; the winding's outer surface.
  const auto& m = solver.mesh();
  const auto& regions = solver.problem().regions;
  const auto& materials = solver.problem().materials;
  double peak = 0.0, coil_r_max = 0.0, coil_z_min = INFINITY, coil_z_max = -INFINITY;
  for (std::size_t e = 0; e < m.triangles.size(); ++e) {
    const auto& region = regions[m.region[e]];
    if (region.material >= 0 && !materials[region.material].bh.empty())
      peak = std::max(peak, results.element_b[e]);
    if (region.circuit != 0) continue;
    for (int k = 0; k < 3; ++k) {
      const mesh::Point p = m.nodes[m.triangles[e][k]];
      coil_r_max = std::max(coil_r_max, p.r);
      coil_z_min = std::min(coil_z_min, p.z);
      coil_z_max = std::max(coil_z_max, p.z);
    }
  }
  q[design::Quantity::peak_steel_b] = peak;
  if (!region_density_.empty()) {
    // Pappus: an element of area A and centroid radius r sweeps 2 pi r A; the closed domain's
    // air regions come after the case's own and have no mass.
    double mass = 0.0;
    for (std::size_t e = 0; e < m.triangles.size(); ++e) {
      if (static_cast<std::size_t>(m.region[e]) >= region_density_.size()) continue;
      const auto& t = m.triangles[e];
      const mesh::Point a = m.nodes[t[0]], b = m.nodes[t[1]], p = m.nodes[t[2]];
      const double area = mesh::triangle_area(a, b, p);
      mass +=
          region_density_[m.region[e]] * 2.0 * std::numbers::pi * (a.r + b.r + p.r) / 3.0 * area;
    }
    q[design::Quantity::mass] = mass;
    q[design::Quantity::torque_per_mass] = q[design::Quantity::torque_on] / mass;
  }

  double r_max = 0.0, z_min = INFINITY, z_max = -INFINITY;
  for (const auto& p : c.problem.geometry.points) {
    r_max = std::max(r_max, p.r);
    z_min = std::min(z_min, p.z);
    z_max = std::max(z_max, p.z);
  }
  q[design::Quantity::outer_radius] = r_max;
  q[design::Quantity::length] = z_max - z_min;
  if (c.input.valve && !c.input.valve->walls().empty()) {
    double thinnest = INFINITY;
    for (const std::string& key : c.input.valve->walls())
      thinnest = std::min(thinnest, c.input.template_values[key]);
    q[design::Quantity::min_wall] = thinnest;
  }

  const valve::CoilSpec coil = valve::coil_spec(solver, valve);
  if (coil.wire_diameter > 0.0) {
    const auto p = valve::coil_properties(coil, on_current, inductance);
    q[design::Quantity::resistance] = p.resistance;
    q[design::Quantity::time_constant] = p.time_constant;
    q[design::Quantity::power] = p.power;
    q[design::Quantity::current_density] = p.current_density;
    q[design::Quantity::copper_fill] = p.copper_fill;
    // Steady temperature rise: all of I^2 R leaves through the coil's outer cylindrical
    // surface (radius = the winding's outer radius, its axial length) with the heat-transfer
    // coefficient h, or through the given thermal resistance.
    const double surface = 2.0 * std::numbers::pi * coil_r_max * (coil_z_max - coil_z_min);
    q[design::Quantity::temperature_rise] = spec_.thermal_resistance > 0.0
                                                ? p.power * spec_.thermal_resistance
                                                : p.power / (spec_.heat_transfer * surface);
    if (uses(spec_, design::Quantity::coil_temperature) ||
        uses(spec_, design::Quantity::fluid_temperature)) {
      thermal::DesignHeat heat;
      heat.coil_power = p.power;
      heat.coil_temperature = coil.temperature;
      heat.fluid_power = fluid_power;
      heat.flow = spec_.flow;
      heat.duty = spec_.duty;
      heat.copper_fill = p.copper_fill;
      const thermal::DeviceTemperatures t = thermal::design_temperatures(c, solver, heat);
      q[design::Quantity::coil_temperature] = t.coil_mean;
      q[design::Quantity::fluid_temperature] = t.fluid_max;
    }
    if (uses(spec_, design::Quantity::rise_time)) {
      const double final_current = spec_.supply_voltage / p.resistance;
      std::vector<double> sample_currents, flux;
      for (int k = 1; k <= kRiseSamples; ++k)
        sample_currents.push_back(0.9 * final_current * k / kRiseSamples);
      for (const auto& point : field.solver->sweep(0, sample_currents))
        flux.push_back(point.flux_linkage);
      designs_.count_solves(kRiseSamples);
      q[design::Quantity::rise_time] =
          rise_time_90(sample_currents, flux, p.resistance, final_current);
    }
    if (uses(spec_, design::Quantity::response_time)) {
      design::ResponseTimeOptions o;
      o.supply_voltage = spec_.supply_voltage;
      o.resistance = p.resistance;
      o.time_constant = p.time_constant;
      o.quasi_static = spec_.response_model == ResponseModel::quasi_static;
      // Finite-difference neighbours reuse the last other design's states and grid (its mesh).
      if (reference_meshes_ == designs_.meshes_built()) o.reuse.start = &reference_;
      // Finite-difference neighbours are linearised about it (its factorisations kept).
      o.reuse.fixed_grid = o.reuse.linearise = neighbour;
      if (!neighbour) {
        o.reuse.keep = &reference_, reference_meshes_ = designs_.meshes_built();
        o.reuse.keep_factor_bytes = kNeighbourFactorBytes;
      }
      const design::ResponseTime t = design::response_time(*field.solver, c, o);
      // the static states of each run, or the reduction's static solves
      designs_.count_solves(2 * t.transient_runs + t.static_solves);
      q[design::Quantity::response_time] =
          t.value() * (o.quasi_static ? response_correction_ : 1.0);
    }
  }
  return q;
}

}  // namespace rheomag::optimise
