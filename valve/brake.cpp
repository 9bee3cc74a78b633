// Brake from a case (brake.hpp): annular gap regions are drums (the inner wall turns, the outer
// is fixed), radial gap regions are single sheared disc faces; torques add.

#include "valve/brake.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "case/femm_sidecar.hpp"
#include "case/toml_section.hpp"
#include "core/error.hpp"
#include "valve/field_solve.hpp"
#include "valve/solved_valve.hpp"

namespace rheomag::valve {

BrakeOptions read_brake_options(const cases::Case& c) {
  BrakeOptions o;
  const cases::TomlSection top(c.table, "", cases::case_document_source(c));
  const auto brake = top.table("brake");
  if (!brake) return o;
  brake->allow_only({"speed", "inner_radius"});
  o.inner_radius = brake->non_negative_or("inner_radius", 0.0);
  o.speeds = brake->numbers("speed");
  return o;
}

SolvedBrake::SolvedBrake(const magnetostatics::MagnetostaticSolver& solver,
                         const magnetostatics::Solution& solution,
                         const magnetostatics::Results& results, const fluid::Fluid& fluid,
                         const BrakeOptions& options)
    : SolvedDevice(solver, solution, results, fluid, "brake", options.inner_radius,
                   "[brake] inner_radius") {}

SolvedBrake SolvedBrake::zero_field() const {
  SolvedBrake off = *this;
  off.clear_field();
  return off;
}

BrakePoint SolvedBrake::point(double speed) const {
  if (!std::isfinite(speed)) throw InputError("brake: speeds must be finite");
  BrakePoint p;
  p.current = current_;
  p.speed = speed;
  p.inductance = inductance_;
  double yielded_area = 0.0, area = 0.0;
  for (const SampledGap& gap : gaps_) {
    BrakeGapResult result;
    result.name = gap.name;
    double wetted = 0.0;
    if (gap.annular) {
      result.kind = "drum";
      const fluid::DrumGeometry g{gap.annulus.inner(), gap.annulus.outer(), gap.annulus.length};
      result.torque = fluid::drum_in_field(g, gap.field, fluid_, speed);
      wetted = 2.0 * std::numbers::pi * g.r_in * g.length;
    } else {
      result.kind = "disc";
      const fluid::DiscGeometry g{gap.radial.r_in, gap.radial.r_out, gap.radial.gap, 1};
      result.torque = fluid::disc_in_field(g, gap.field, fluid_, speed);
      wetted = std::numbers::pi * (g.r_out * g.r_out - g.r_in * g.r_in);
    }
    double sum = 0.0;
    for (double b : gap.field.b) sum += b;
    result.b_average = sum / static_cast<double>(gap.field.b.size());
    p.torque.torque += result.torque.torque;
    p.torque.torque_yield += result.torque.torque_yield;
    p.torque.torque_viscous += result.torque.torque_viscous;
    p.torque.breakaway_torque += result.torque.breakaway_torque;
    yielded_area += result.torque.yielded_fraction * wetted;
    area += wetted;
    p.gaps.push_back(std::move(result));
  }
  p.torque.yielded_fraction = yielded_area / area;
  return p;
}

BrakeChain::BrakeChain(const cases::Case& c, BrakeOptions options)
    : DeviceChain(c, "brake"), options_(std::move(options)) {}

std::vector<BrakePoint> BrakeChain::evaluate(const std::vector<double>& currents,
                                             const std::vector<double>& speeds) {
  return per_current<BrakePoint>(currents, speeds.size(), "speed",
                                 [&](const magnetostatics::MagnetostaticSolver& solver,
                                     const DeviceField& field, const PointDone& point_done) {
                                   const SolvedBrake brake(solver, field.solution, field.results,
                                                           fluid_, options_);
                                   std::vector<BrakePoint> points;
                                   for (double w : speeds) {
                                     points.push_back(brake.point(w));
                                     point_done();
                                   }
                                   return points;
                                 });
}

}  // namespace rheomag::valve
