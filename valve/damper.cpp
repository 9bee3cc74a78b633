// Damper from a piston case (damper.hpp). Kinematics of a monotube: the piston (radius R_p, the
// gaps' inner wall) moves at v (> 0 into the compression chamber), the rod (radius R_r) enters
// the rebound side, the accumulator takes the rod's volume. Incompressible chambers:
//   gap wall = cylinder: in the tube's frame the gap carries Q = pi (R_p^2 - R_r^2) v from the
//     compression to the rebound chamber while its inner wall moves at U = -v along that flow;
//   gap wall = piston (flux ring): in the piston's frame Q = pi (R_b^2 - R_r^2) v, U = 0.
// Force on piston and rod against the motion (compression chamber at the gas pressure p_g,
// rebound chamber at p_g - dp):  F = dp A_eff + F_wall + p_g pi R_r^2, with A_eff the area
// multiplying v above and F_wall the fluid's shear on the piston's gap walls along the flow
// (cylinder wall only). Gas: p V^k = const, V = V_0 -+ pi R_r^2 stroke / 2 at the stroke ends.

#include "valve/damper.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "case/femm_sidecar.hpp"
#include "case/toml_section.hpp"
#include "core/error.hpp"
#include "valve/field_solve.hpp"
#include "valve/solved_valve.hpp"

namespace rheomag::valve {

namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

DamperOptions read_damper_options(const cases::Case& c) {
  const cases::TomlSection top(c.table, "", cases::case_document_source(c));
  const auto damper = top.table("damper");
  if (!damper)
    throw InputError(c.source.string() +
                     ": the case has no [damper] table (rod_diameter, "
                     "gas_pressure, ...; docs/dampers.md)");
  damper->allow_only({"rod_diameter", "bore", "gas_pressure", "gas_volume", "stroke",
                      "polytropic_index", "gap_wall", "velocity"});
  DamperOptions o;
  o.rod_diameter = damper->non_negative_or("rod_diameter", 0.0);
  o.bore = damper->non_negative_or("bore", 0.0);
  o.gas_pressure = damper->non_negative_or("gas_pressure", 0.0);
  o.gas_volume = damper->non_negative_or("gas_volume", 0.0);
  o.stroke = damper->non_negative_or("stroke", 0.0);
  o.polytropic_index = damper->positive_or("polytropic_index", 1.0);
  if (auto wall = damper->string("gap_wall"))
    o.gap_wall = kGapWallNames.parse(*wall, damper->where("gap_wall"));
  if (o.gap_wall == GapWall::piston && !(o.bore > 0.0))
    damper->fail("bore", "gap_wall = \"piston\" needs the cylinder bore diameter (m)");
  if (o.gas_volume > 0.0 &&
      !(o.gas_volume > kPi * o.rod_diameter * o.rod_diameter / 4.0 * o.stroke / 2.0))
    damper->fail("gas_volume", "the rod's volume over half the stroke must fit in the gas volume");
  o.velocities = damper->numbers("velocity");
  return o;
}

std::pair<double, double> gas_force_range(const DamperOptions& o) {
  const double rod_area = kPi * o.rod_diameter * o.rod_diameter / 4.0;
  const double p0 = o.gas_pressure, v0 = o.gas_volume;
  if (!(v0 > 0.0)) return {p0 * rod_area, p0 * rod_area};
  const double dv = rod_area * o.stroke / 2.0, k = o.polytropic_index;
  return {p0 * std::pow(v0 / (v0 + dv), k) * rod_area, p0 * std::pow(v0 / (v0 - dv), k) * rod_area};
}

SolvedDamper::SolvedDamper(const magnetostatics::MagnetostaticSolver& solver,
                           const magnetostatics::Solution& solution,
                           const magnetostatics::Results& results, const fluid::Fluid& fluid,
                           const DamperOptions& options)
    : SolvedDevice(solver, solution, results, fluid, "damper"), options_(options) {
  const std::string where = solver.problem().geometry.source;
  for (const SampledGap& gap : gaps_)
    if (!gap.annular)
      throw InputError(where + ": damper gap \"" + gap.name +
                       "\" is radial; a piston's gaps must be annular");
  piston_radius_ = gaps_.front().annulus.inner();
  const double outer = gaps_.front().annulus.outer();
  for (const SampledGap& gap : gaps_)
    if (std::abs(gap.annulus.inner() - piston_radius_) > 1e-6 * outer ||
        std::abs(gap.annulus.outer() - outer) > 1e-6 * outer)
      throw InputError(where + ": damper gap \"" + gap.name +
                       "\" does not lie between the same radii as \"" + gaps_.front().name + "\"");
  const double rod_radius = 0.5 * options_.rod_diameter;
  const double outer_radius =
      options_.gap_wall == GapWall::cylinder ? piston_radius_ : 0.5 * options_.bore;
  if (!(rod_radius < outer_radius))
    throw InputError(where + ": [damper] rod_diameter does not fit inside the piston");
  rod_area_ = kPi * rod_radius * rod_radius;
  piston_area_ = kPi * outer_radius * outer_radius - rod_area_;
}

SolvedDamper SolvedDamper::zero_field() const {
  SolvedDamper off = *this;
  off.clear_field();
  return off;
}

DamperPoint SolvedDamper::point(double velocity) const {
  if (!std::isfinite(velocity)) throw InputError("damper: velocities must be finite");
  DamperPoint p;
  p.current = current_;
  p.inductance = inductance_;
  p.velocity = velocity;
  p.force_gas = options_.gas_pressure * rod_area_;
  const bool moving_wall = options_.gap_wall == GapWall::cylinder;
  p.flow = piston_area_ * velocity;
  p.wall_velocity = moving_wall ? -velocity : 0.0;
  // Still-walled gaps are odd in the flow: solve at |v| and mirror.
  const double sign = !moving_wall && velocity < 0.0 ? -1.0 : 1.0;
  for (const SampledGap& gap : gaps_) {
    DamperGapResult result;
    result.name = gap.name;
    if (velocity != 0.0) {
      result.drop = fluid::moving_annular_gap_in_field(gap.annulus, gap.field, fluid_,
                                                       p.wall_velocity, sign * p.flow);
      result.drop.dp *= sign;
      result.drop.dp_viscous *= sign;
      result.drop.dp_yield *= sign;
      result.drop.wall_force *= sign;
    } else {
      result.drop.regime = fluid::MixedRegime::unyielded;
      result.drop.plug_fraction = 1.0;
    }
    p.dp += result.drop.dp;
    p.dp_viscous += result.drop.dp_viscous;
    if (moving_wall) p.force_wall += result.drop.wall_force;
    p.gaps.push_back(std::move(result));
  }
  p.force_pressure = p.dp * piston_area_;
  p.force = p.force_pressure + p.force_wall + p.force_gas;
  return p;
}

DamperChain::DamperChain(const cases::Case& c, DamperOptions options)
    : DeviceChain(c, "damper"), options_(std::move(options)) {}

std::vector<DamperPoint> DamperChain::evaluate(const std::vector<double>& currents,
                                               const std::vector<double>& velocities) {
  return evaluate_at(currents, velocities, false);
}

std::vector<DamperPoint> DamperChain::evaluate_flows(const std::vector<double>& currents,
                                                     const std::vector<double>& flows) {
  return evaluate_at(currents, flows, true);
}

std::vector<DamperPoint> DamperChain::evaluate_at(const std::vector<double>& currents,
                                                  const std::vector<double>& values, bool flows) {
  return per_current<DamperPoint>(
      currents, values.size(), "velocity",
      [&](const magnetostatics::MagnetostaticSolver& solver, const DeviceField& field,
          const PointDone& point_done) {
        const SolvedDamper damper(solver, field.solution, field.results, fluid_, options_);
        std::vector<DamperPoint> points;
        for (double value : values) {
          points.push_back(damper.point(flows ? value / damper.piston_area() : value));
          point_done();
        }
        return points;
      });
}

}  // namespace rheomag::valve
