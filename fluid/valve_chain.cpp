// Valve chain: every fluid gap region of the case (RegionSeed::gap annular or radial) is a
// segment in series (the flow passes each gap once; paper 000's valve: the two pole gaps).
// Segment geometry is the gap's rectangle in the meridian plane (GapResult mid-line and area):
// annular: mean radius = mid-line r, length = its z extent, clearance = area / length; radial:
// r_in..r_out = the mid-line's r extent (r_in raised to [valve] inlet_radius), clearance =
// area / (r_out - r_in). The normal flux density |B_n| is sampled at 101 mid-line points and
// fed to field_coupling. Unmagnetised passages of the flow path are not in the case geometry
// and are not included. Coil: turns and the winding window (area, area-weighted mean radius)
// from the coil regions of the mesh; resistance etc. from coil.cpp.

#include "fluid/valve_chain.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "magnetostatics/material_library.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/toml_section.hpp"
#include "mesh/error.hpp"

namespace rheomag::fluid {

namespace {

constexpr int kSamples = 101;

GapFieldSamples sample_gap(const magnetostatics::MagnetostaticSolver& solver,
                           const magnetostatics::Solution& solution,
                           const magnetostatics::GapResult& gap, double start_offset) {
  GapFieldSamples field;
  const double dr = gap.line_end.r - gap.line_start.r, dz = gap.line_end.z - gap.line_start.z;
  const double length = std::hypot(dr, dz);
  for (int i = 0; i < kSamples; ++i) {
    const double t = (i + 0.5) / kSamples;
    const mesh::Point p{gap.line_start.r + t * dr, gap.line_start.z + t * dz};
    std::array<double, 2> b{};
    if (!magnetostatics::flux_density_at(solver, solution, p, gap.region, b)) continue;
    const double position = gap.kind == mesh::GapKind::annular ? t * length : p.r;
    if (position < start_offset) continue;
    field.position.push_back(position);
    field.b.push_back(gap.kind == mesh::GapKind::annular ? b[0] : b[1]);
  }
  if (field.position.size() < 2)
    throw InputError("gap \"" + gap.name + "\": fewer than 2 mid-line field samples found");
  return field;
}

}  // namespace

ValveOptions read_valve_options(const magnetostatics::Case& c) {
  ValveOptions options;
  const magnetostatics::TomlSection top(c.table, "", c.source.string());
  auto valve = top.table("valve");
  if (!valve) return options;
  valve->allow_only({"wire", "temperature", "inlet_radius", "flow"});
  options.wire = valve->string("wire").value_or("");
  options.temperature = valve->number_or("temperature", 20.0);
  options.inlet_radius = valve->non_negative_or("inlet_radius", 0.0);
  if (auto flow = valve->number("flow")) {
    if (!(*flow > 0.0)) throw InputError(c.source.string() + ": [valve].flow must be > 0 m^3/s");
    options.flows = {*flow};
  }
  return options;
}

ValveChain::ValveChain(const magnetostatics::Case& c, ValveOptions options)
    : options_(std::move(options)) {
  const std::string where = c.source.string();
  if (c.fluid.empty()) throw InputError(where + ": the case names no MR fluid ([case] fluid)");
  const auto& material = magnetostatics::MaterialLibrary::standard().get(c.fluid, where);
  fluid_ = read_fluid(material.file);
  if (c.problem.circuits.empty()) throw InputError(where + ": the case has no coil circuit");
  solved_ = magnetostatics::solve_problem(c.problem);
  if (solved_.results.gaps.empty()) throw InputError(where + ": the case has no fluid gap");
  // Winding window of circuit 0 from the mesh: area and area-weighted mean radius.
  const auto& mesh = solved_.solver->mesh();
  const auto& regions = solved_.solver->problem().regions;
  double area = 0.0, moment = 0.0;
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
    const auto& region = regions[mesh.region[e]];
    if (region.circuit != 0) continue;
    const auto& t = mesh.triangles[e];
    const mesh::Point a = mesh.nodes[t[0]], b = mesh.nodes[t[1]], d = mesh.nodes[t[2]];
    const double triangle = 0.5 * std::abs((b.r - a.r) * (d.z - a.z) - (d.r - a.r) * (b.z - a.z));
    area += triangle;
    moment += triangle * (a.r + b.r + d.r) / 3.0;
  }
  double turns = 0.0;
  for (const auto& region : regions)
    if (region.circuit == 0) turns += std::abs(region.turns);
  if (!(area > 0.0) || !(turns > 0.0))
    throw InputError(where + ": circuit \"" + c.problem.circuits[0].name + "\" has no coil turns");
  coil_.turns = turns;
  coil_.window_area = area;
  coil_.mean_turn_length = 2.0 * std::numbers::pi * moment / area;
  coil_.temperature = options_.temperature;
  if (!options_.wire.empty()) coil_.wire_diameter = wire_diameter(options_.wire);
}

std::vector<ValvePoint> ValveChain::evaluate(const std::vector<double>& currents,
                                             const std::vector<double>& flows) {
  if (currents.empty() || flows.empty())
    throw InputError("valve: needs at least one current and one flow rate");
  std::vector<ValvePoint> points;
  const auto& solver = *solved_.solver;
  const std::size_t circuits = solver.problem().circuits.size();
  for (double current : currents) {
    if (!std::isfinite(current)) throw InputError("valve: currents must be finite");
    std::vector<double> per_circuit(circuits, 0.0);
    for (std::size_t k = 1; k < circuits; ++k)
      per_circuit[k] = solver.problem().circuits[k].current;
    per_circuit[0] = current;
    const auto solution = solved_.solver->solve(per_circuit);
    const auto results = magnetostatics::compute_results(solver, solution);
    std::vector<GapFieldSamples> fields;
    for (const auto& gap : results.gaps)
      fields.push_back(sample_gap(solver, solution, gap,
                                  gap.kind == mesh::GapKind::radial ? options_.inlet_radius : 0.0));
    for (double flow : flows) {
      if (!(std::isfinite(flow) && flow > 0.0))
        throw InputError("valve: flow rates must be > 0 m^3/s");
      ValvePoint point;
      point.current = current;
      point.flow = flow;
      point.inductance = results.circuits.empty() ? 0.0 : results.circuits[0].inductance;
      for (std::size_t g = 0; g < results.gaps.size(); ++g) {
        const auto& gap = results.gaps[g];
        SegmentResult segment;
        segment.name = gap.name;
        const double dr = std::abs(gap.line_end.r - gap.line_start.r);
        const double dz = std::abs(gap.line_end.z - gap.line_start.z);
        if (gap.kind == mesh::GapKind::annular) {
          segment.kind = "annular";
          const AnnulusGeometry geometry{gap.area / dz, gap.line_start.r, dz};
          segment.drop = annular_gap_in_field(geometry, fields[g], fluid_, flow);
        } else {
          segment.kind = "radial";
          const double r_in =
              std::max(std::min(gap.line_start.r, gap.line_end.r), options_.inlet_radius);
          const double r_out = std::max(gap.line_start.r, gap.line_end.r);
          if (!(r_in > 0.0))
            throw InputError("gap \"" + gap.name +
                             "\" starts on the axis: set [valve] inlet_radius (m) to the radius "
                             "where the flow enters it");
          const RadialGeometry geometry{gap.area / dr, r_in, r_out};
          segment.drop = radial_gap_in_field(geometry, fields[g], fluid_, flow);
        }
        segment.b_average = segment.drop.b_average;
        point.dp_total += segment.drop.integrated.dp;
        point.dp_viscous += segment.drop.integrated.dp_viscous;
        point.dp_total_average_b += segment.drop.average_b.dp;
        point.segments.push_back(std::move(segment));
      }
      point.dp_yield = point.dp_total - point.dp_viscous;
      if (std::abs(point.dp_yield) <= 1e-12 * point.dp_total) point.dp_yield = 0.0;  // rounding
      points.push_back(std::move(point));
    }
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

}  // namespace rheomag::fluid
