// Solved valve: the gaps' geometry and mid-line |B_n| from sample_gaps (sampled_gaps.hpp; radial
// gaps start at [valve] inlet_radius), fed to field_coupling, then passages and losses.

#include "valve/solved_valve.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "case/femm_sidecar.hpp"
#include "case/material_library.hpp"
#include "core/error.hpp"
#include "fluid/newtonian.hpp"
#include "mesh/triangle.hpp"

namespace rheomag::valve {

namespace {

/// Bounding box (r_min, r_max, z_min, z_max) of the mesh elements of the region named `name`.
std::array<double, 4> region_box(const magnetostatics::MagnetostaticSolver& solver,
                                 const std::string& name, const std::string& passage) {
  const auto& regions = solver.problem().geometry.regions;
  int index = -1;
  for (std::size_t i = 0; i < regions.size(); ++i)
    if (regions[i].name == name) index = static_cast<int>(i);
  if (index < 0)
    throw InputError("[[valve.passage]] \"" + passage + "\": the case has no region \"" + name +
                     "\"");
  std::array<double, 4> box{INFINITY, -INFINITY, INFINITY, -INFINITY};
  const auto& mesh = solver.mesh();
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
    if (mesh.region[e] != index) continue;
    for (int node : mesh.triangles[e]) {
      const mesh::Point& p = mesh.nodes[node];
      box = {std::min(box[0], p.r), std::max(box[1], p.r), std::min(box[2], p.z),
             std::max(box[3], p.z)};
    }
  }
  if (!(box[1] > box[0]))
    throw InputError("[[valve.passage]] \"" + passage + "\": region \"" + name + "\" is empty");
  return box;
}

/// The passage with its dimensions taken from its region (if it names one), validated.
fluid::Passage resolve_passage(const magnetostatics::MagnetostaticSolver& solver,
                               fluid::Passage p) {
  if (!p.region.empty()) {
    const auto box = region_box(solver, p.region, p.name);
    const double r_min = box[0] <= 1e-9 * box[1] ? 0.0 : box[0];
    switch (p.shape) {
      case fluid::PassageShape::pipe:
        if (r_min > 0.0)
          throw InputError("[[valve.passage]] \"" + p.name + "\": region \"" + p.region +
                           "\" does not touch the axis; use shape = \"annulus\"");
        p.diameter = 2.0 * box[1];
        p.length = box[3] - box[2];
        break;
      case fluid::PassageShape::annulus:
      case fluid::PassageShape::radial:
        p.inner_radius = r_min;
        p.outer_radius = box[1];
        (p.shape == fluid::PassageShape::annulus ? p.length : p.gap) = box[3] - box[2];
        break;
      case fluid::PassageShape::slit:
        break;  // rejected by fluid::read_passages
    }
  }
  validate(p);
  return p;
}

}  // namespace

fluid::Fluid case_fluid(const cases::Case& c) {
  const std::string where = c.source.string();
  if (c.fluid.empty() && c.femm) {
    throw InputError(where + ": a FEMM model names its MR fluid and gaps in a sidecar beside it, " +
                     cases::femm_sidecar_path(c.source).string() +
                     " ([fem] fluid and [[fem.gap]] label or block, docs/femm.md); 'rheomag "
                     "export CASE --fem MODEL.fem' writes both");
  }
  if (c.fluid.empty()) throw InputError(where + ": the case names no MR fluid ([case] fluid)");
  return fluid::read_fluid(cases::MaterialLibrary::standard().get(c.fluid, where).file);
}

CoilSpec coil_spec(const magnetostatics::MagnetostaticSolver& solver, const ValveOptions& options) {
  const auto& mesh = solver.mesh();
  const auto& problem = solver.problem();
  const std::string where = problem.geometry.source;
  if (problem.circuits.empty()) throw InputError(where + ": the case has no coil circuit");
  double area = 0.0, moment = 0.0;
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
    if (problem.regions[mesh.region[e]].circuit != 0) continue;
    const auto& t = mesh.triangles[e];
    const mesh::Point a = mesh.nodes[t[0]], b = mesh.nodes[t[1]], d = mesh.nodes[t[2]];
    const double triangle = mesh::triangle_area(a, b, d);
    area += triangle;
    moment += triangle * (a.r + b.r + d.r) / 3.0;
  }
  double turns = 0.0;
  for (const auto& region : problem.regions)
    if (region.circuit == 0) turns += std::abs(region.turns);
  if (!(area > 0.0) || !(turns > 0.0))
    throw InputError(where + ": circuit \"" + problem.circuits[0].name + "\" has no coil turns");
  CoilSpec spec;
  spec.turns = turns;
  spec.window_area = area;
  spec.mean_turn_length = 2.0 * std::numbers::pi * moment / area;
  spec.temperature = options.temperature;
  if (options.wire_diameter > 0.0)
    spec.wire_diameter = options.wire_diameter;
  else if (!options.wire.empty())
    spec.wire_diameter = wire_diameter(options.wire);
  return spec;
}

std::optional<double> wire_resistance(const cases::Case& c,
                                      const magnetostatics::MagnetostaticSolver& solver) {
  const ValveOptions options = read_valve_options(c);
  if (options.wire.empty()) return std::nullopt;
  return coil_properties(coil_spec(solver, options), 0.0, 0.0).resistance;
}

SolvedValve::SolvedValve(const magnetostatics::MagnetostaticSolver& solver,
                         const magnetostatics::Solution& solution,
                         const magnetostatics::Results& results, const fluid::Fluid& fluid,
                         const ValveOptions& options)
    : fluid_(fluid), options_(options) {
  if (results.gaps.empty())
    throw InputError(solver.problem().geometry.source + ": the case has no fluid gap");
  if (!results.circuits.empty()) {
    const auto& circuit = results.circuits.front();
    current_ = circuit.current;
    flux_linkage_ = circuit.flux_linkage;
    inductance_ = circuit.inductance;
    incremental_ = circuit.incremental_inductance;
  }
  double b_sum = 0.0;
  std::size_t b_count = 0;
  min_clearance_ = INFINITY;
  gaps_ = sample_gaps(solver, solution, results, options_.inlet_radius);
  for (const SampledGap& gap : gaps_) {
    for (double b : gap.field.b) b_sum += b;
    b_count += gap.field.b.size();
    min_clearance_ = std::min(min_clearance_, gap.annular ? gap.annulus.gap : gap.radial.gap);
  }
  b_average_ = b_sum / static_cast<double>(b_count);
  for (const fluid::Passage& passage : options_.passages)
    passages_.push_back(resolve_passage(solver, passage));
  for (const fluid::MinorLoss& loss : options_.losses)
    losses_.push_back({loss, section_area(loss)});
}

double SolvedValve::section_area(const fluid::MinorLoss& loss) const {
  if (loss.section.empty()) return loss.area;
  const std::string what = "[[valve.loss]] \"" + loss.name + "\": section \"" + loss.section + "\"";
  for (const fluid::Passage& p : passages_)
    if (p.name == loss.section) {
      if (p.shape == fluid::PassageShape::radial && !(loss.radius > 0.0))
        throw InputError(what + " is radial: give radius (m) where the velocity is taken");
      return fluid::passage_area(p, loss.radius);
    }
  for (const SampledGap& gap : gaps_) {
    if (gap.name != loss.section) continue;
    if (gap.annular) return 2.0 * std::numbers::pi * gap.annulus.radius * gap.annulus.gap;
    if (!(loss.radius >= gap.radial.r_in && loss.radius <= gap.radial.r_out))
      throw InputError(what + " is a radial gap: give radius (m) within " +
                       std::to_string(gap.radial.r_in) + ".." + std::to_string(gap.radial.r_out));
    return 2.0 * std::numbers::pi * loss.radius * gap.radial.gap;
  }
  throw InputError(what + " is neither a gap nor a passage of the valve");
}

ValvePoint SolvedValve::point(double flow) const {
  return evaluate(flow, false);
}

ValvePoint SolvedValve::zero_field_point(double flow) const {
  return evaluate(flow, true);
}

ValvePoint SolvedValve::evaluate(double flow, bool zero_field) const {
  if (!(std::isfinite(flow) && flow > 0.0)) throw InputError("valve: flow rates must be > 0 m^3/s");
  ValvePoint point;
  point.current = zero_field ? 0.0 : current_;
  point.flow = flow;
  if (!zero_field) {
    point.flux_linkage = flux_linkage_;
    point.inductance = inductance_;
    point.incremental_inductance = incremental_;
  }
  for (const SampledGap& gap : gaps_) {
    SegmentResult segment;
    segment.name = gap.name;
    fluid::GapFieldSamples field = gap.field;
    if (zero_field) std::fill(field.b.begin(), field.b.end(), 0.0);
    if (gap.annular) {
      segment.kind = SegmentKind::annular;
      segment.drop = fluid::annular_gap_in_field(gap.annulus, field, fluid_, flow);
    } else {
      segment.kind = SegmentKind::radial;
      segment.drop = fluid::radial_gap_in_field(gap.radial, field, fluid_, flow);
    }
    segment.b_average = segment.drop.b_average;
    segment.field = std::move(field);
    point.dp_total += segment.drop.integrated.dp;
    point.dp_viscous += segment.drop.integrated.dp_viscous;
    point.dp_total_average_b += segment.drop.average_b.dp;
    point.segments.push_back(std::move(segment));
  }
  // Field-independent parts: Newtonian passages and minor losses (in dp_viscous, which is the
  // tau_y = 0 drop of the whole path).
  auto add = [&point](SegmentResult segment, double dp) {
    segment.drop.integrated.dp = segment.drop.integrated.dp_viscous = dp;
    segment.drop.average_b = segment.drop.integrated;
    point.dp_total += dp;
    point.dp_viscous += dp;
    point.dp_total_average_b += dp;
    point.segments.push_back(std::move(segment));
  };
  for (const fluid::Passage& passage : passages_) {
    SegmentResult segment;
    segment.name = passage.name;
    segment.kind = SegmentKind::passage;
    segment.reynolds_number = fluid::reynolds_number(
        fluid_.density, fluid_.viscosity, flow, fluid::passage_area(passage, passage.inner_radius),
        fluid::hydraulic_diameter(passage));
    add(std::move(segment), fluid::passage_dp(passage, fluid_.viscosity, flow));
  }
  for (const Loss& loss : losses_) {
    SegmentResult segment;
    segment.name = loss.loss.name;
    segment.kind = SegmentKind::loss;
    add(std::move(segment), fluid::minor_loss_dp(loss.loss.k, fluid_.density, flow, loss.area));
  }
  point.dp_yield = point.dp_total - point.dp_viscous;
  if (std::abs(point.dp_yield) <= 1e-12 * point.dp_total) point.dp_yield = 0.0;  // rounding
  return point;
}

}  // namespace rheomag::valve
