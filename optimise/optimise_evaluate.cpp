// Gap pressure drops from fluid::SolvedValve (the valve chain on the already solved field: every
// gap in series, local tau_y(B(s)) along each mid-line; off state: B = 0). Coil: fluid::coil_spec
// (turns and winding window from the circuit-0 regions of the (morphed) mesh).

#include "optimise/optimise_evaluate.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "fluid/coil.hpp"
#include "fluid/solved_valve.hpp"
#include "fluid/valve_chain.hpp"
#include "magnetostatics/domain.hpp"
#include "magnetostatics/material_library.hpp"
#include "mesh/error.hpp"
#include "mesh/mesher.hpp"
#include "optimise/optimise_case_edit.hpp"
#include "optimise/optimise_wire_gauge.hpp"

namespace rheomag::optimise {

namespace {

constexpr int kRiseSamples = 4;  // lambda(i) samples of the rise-time integral

// The steel walls of each parametric template (thicknesses, file units): the ring outside the
// gap and the pole flanges (annular), shell and plates (radial), shell, plates and lips
// (meandering).
const std::map<std::string, std::vector<std::string>>& template_walls() {
  static const std::map<std::string, std::vector<std::string>> walls = {
      {"annular_valve", {"disk_thickness", "pole_length"}},
      {"radial_valve", {"shell_thickness", "plate_thickness"}},
      {"meandering_valve", {"shell_thickness", "plate_thickness", "lip_thickness"}}};
  return walls;
}

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

DesignEvaluator::DesignEvaluator(magnetostatics::Case base, OptimiseSpec spec)
    : base_(std::move(base)), spec_(std::move(spec)) {
  const std::string where = base_.source.string();
  for (const auto& v : spec_.variables) keys_.push_back(v.key);
  for (std::size_t i = 0; i < keys_.size(); ++i)
    if (keys_[i] == kWireGaugeKey) gauge_index_ = static_cast<int>(i);
  fluid_ = fluid::case_fluid(base_);
  if (base_.problem.circuits.empty()) throw InputError(where + ": the case has no coil circuit");
  const std::string wire = fluid::read_valve_options(base_).wire;
  static const std::vector<std::string> needs_wire = {
      "resistance",  "time_constant",    "power",    "current_density",
      "copper_fill", "temperature_rise", "rise_time"};
  const auto used = used_quantities(spec_);
  auto uses = [&](const std::string& q) {
    return std::find(used.begin(), used.end(), q) != used.end();
  };
  for (const auto& q : needs_wire)
    if (wire.empty() && uses(q))
      throw InputError(where + ": \"" + q +
                       "\" needs the coil wire: set [valve] wire = \"AWG 24\" (or \"0.5 mm\")");
  need_rise_time_ = uses("rise_time");
  if (uses("min_wall") && !template_walls().count(base_.geometry_template))
    throw InputError(where +
                     ": \"min_wall\" needs a parametric template (annular_valve, "
                     "radial_valve, meandering_valve); this case has none");
}

magnetostatics::Case DesignEvaluator::case_at(const std::vector<double>& x) const {
  if (gauge_index_ < 0)
    return case_from_table(with_values(base_.table, keys_, x), base_.source.string());
  std::vector<std::string> keys = keys_;
  std::vector<double> values = x;
  keys.erase(keys.begin() + gauge_index_);
  values.erase(values.begin() + gauge_index_);
  return case_from_table(with_text(with_values(base_.table, keys, values), "geometry.wire",
                                   wire_text(x[gauge_index_])),
                         base_.source.string());
}

mesh::Mesh DesignEvaluator::mesh_for(const magnetostatics::Problem& closed,
                                     const Breakpoints& breakpoints) {
  if (have_mesh_) {
    if (auto morphed = morph_mesh(reference_mesh_, reference_breakpoints_, breakpoints))
      return std::move(*morphed);
  }
  mesh::MeshOptions options;
  options.order = closed.order;
  options.min_gap_elements = closed.min_gap_elements;
  reference_mesh_ = mesh::generate_mesh(closed.geometry, options);
  reference_breakpoints_ = breakpoints;
  have_mesh_ = true;
  ++meshes_;
  return reference_mesh_;
}

Quantities DesignEvaluator::evaluate(const std::vector<double>& x) {
  const auto c = case_at(x);
  const auto breakpoints = geometry_breakpoints(c.problem.geometry);
  magnetostatics::Problem closed = magnetostatics::close_domain(c.problem);
  mesh::Mesh mesh = mesh_for(closed, breakpoints);
  if (gauge_index_ >= 0 && !exact_winding_) {
    // Continuous relaxation: turns = fill A_window / (pi d(n)^2 / 4) without the case's floor,
    // so the turns (and everything after) are smooth in the gauge and the window.
    const double fill = c.table["geometry"]["fill_factor"].value_or(0.0);
    const double d = awg_diameter_relaxed(x[gauge_index_]);
    std::vector<double> window(closed.regions.size(), 0.0);
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
      const auto& t = mesh.triangles[e];
      const mesh::Point a = mesh.nodes[t[0]], b = mesh.nodes[t[1]], p = mesh.nodes[t[2]];
      window[mesh.region[e]] +=
          0.5 * std::abs((b.r - a.r) * (p.z - a.z) - (p.r - a.r) * (b.z - a.z));
    }
    for (std::size_t k = 0; k < closed.regions.size(); ++k)
      if (closed.regions[k].circuit >= 0 && closed.regions[k].turns != 0.0)
        closed.regions[k].turns = std::copysign(
            fill * window[k] / (0.25 * std::numbers::pi * d * d), closed.regions[k].turns);
  }
  magnetostatics::SolveOptions options;
  options.incremental_inductance = false;
  auto solver =
      std::make_unique<magnetostatics::MagnetostaticSolver>(closed, std::move(mesh), options);
  std::vector<double> currents(closed.circuits.size(), 0.0);
  for (std::size_t k = 1; k < currents.size(); ++k) currents[k] = closed.circuits[k].current;
  currents[0] = spec_.current;
  auto solution = solver->solve(currents);
  ++fe_solves_;
  auto results = magnetostatics::compute_results(*solver, solution);
  if (results.gaps.empty()) throw InputError(base_.source.string() + ": the case has no fluid gap");

  Quantities q;
  const auto valve = fluid::read_valve_options(c);
  const fluid::SolvedValve solved(*solver, solution, results, fluid_, valve);
  const auto on = solved.point(spec_.flow);
  q["dp_on"] = on.dp_total;
  q["dp_off"] = solved.zero_field_point(spec_.flow).dp_total;
  q["dynamic_range"] = q["dp_on"] / q["dp_off"];
  q["b_gap"] = solved.b_average();
  q["min_gap"] = solved.min_clearance();
  const double inductance = on.inductance;
  q["inductance"] = inductance;

  // Peak |B| over the elements of nonlinear (steel) materials; the winding's outer surface.
  const auto& m = solver->mesh();
  const auto& regions = solver->problem().regions;
  const auto& materials = solver->problem().materials;
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
  q["peak_steel_b"] = peak;

  double r_max = 0.0, z_min = INFINITY, z_max = -INFINITY;
  for (const auto& p : c.problem.geometry.points) {
    r_max = std::max(r_max, p.r);
    z_min = std::min(z_min, p.z);
    z_max = std::max(z_max, p.z);
  }
  q["outer_radius"] = r_max;
  q["length"] = z_max - z_min;
  if (auto walls = template_walls().find(c.geometry_template); walls != template_walls().end()) {
    const double unit = c.table["case"]["units"].value_or(std::string("m")) == "mm" ? 1e-3 : 1.0;
    double thinnest = INFINITY;
    for (const auto& key : walls->second)
      thinnest = std::min(thinnest,
                          unit * numeric_case_value(c.table, "geometry." + key, c.source.string()));
    q["min_wall"] = thinnest;
  }

  const fluid::CoilSpec coil = fluid::coil_spec(*solver, valve);
  if (coil.wire_diameter > 0.0) {
    const auto p = fluid::coil_properties(coil, spec_.current, inductance);
    q["resistance"] = p.resistance;
    q["time_constant"] = p.time_constant;
    q["power"] = p.power;
    q["current_density"] = p.current_density;
    q["copper_fill"] = p.copper_fill;
    // Steady temperature rise: all of I^2 R leaves through the coil's outer cylindrical
    // surface (radius = the winding's outer radius, its axial length) with the heat-transfer
    // coefficient h, or through the given thermal resistance.
    const double surface = 2.0 * std::numbers::pi * coil_r_max * (coil_z_max - coil_z_min);
    q["temperature_rise"] = spec_.thermal_resistance > 0.0
                                ? p.power * spec_.thermal_resistance
                                : p.power / (spec_.heat_transfer * surface);
    if (need_rise_time_) {
      const double final_current = spec_.supply_voltage / p.resistance;
      std::vector<double> sample_currents, flux;
      for (int k = 1; k <= kRiseSamples; ++k)
        sample_currents.push_back(0.9 * final_current * k / kRiseSamples);
      for (const auto& point : solver->sweep(0, sample_currents))
        flux.push_back(point.flux_linkage);
      fe_solves_ += kRiseSamples;
      q["rise_time"] = rise_time_90(sample_currents, flux, p.resistance, final_current);
    }
  }
  last_.solver = std::move(solver);
  last_.solution = std::move(solution);
  last_.results = std::move(results);
  return q;
}

}  // namespace rheomag::optimise
