// Damper and brake gaps in a sampled field (device_in_field.hpp). Like field_coupling.cpp: the
// field varies slowly compared with the gap, so each position is a fully developed flow at the
// local yield stress, integrated over the samples by the trapezoidal rule.

#include "fluid/device_in_field.hpp"

#include <cmath>
#include <vector>

namespace rheomag::fluid {

namespace {

/// Index of the sample nearest `at`.
std::size_t nearest(const std::vector<double>& x, double at) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < x.size(); ++i)
    if (std::abs(x[i] - at) < std::abs(x[best] - at)) best = i;
  return best;
}

}  // namespace

MovingGapDrop moving_annular_gap_in_field(const AnnulusGeometry& g, const GapFieldSamples& field,
                                          const Fluid& fluid, double wall_velocity, double flow) {
  validate(g);
  check_field_samples(field, 0.0, g.length, "annular gap field");
  const auto& x = field.position;
  const std::vector<double> b = sample_magnitudes(field.b);
  const AnnulusGeometry unit{g.gap, g.radius, 1.0};  // dp and wall force of a unit length
  std::vector<double> gradient(x.size()), wall_force(x.size());
  MovingGapDrop out;
  const std::size_t middle = nearest(x, 0.5 * g.length);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const GapRheology local{fluid.yield_stress(b[i]), fluid.viscosity, fluid.flow_index};
    const MixedModeDrop d = annulus_mixed_mode(unit, local, wall_velocity, flow);
    gradient[i] = d.drop.dp;
    wall_force[i] = d.moving_wall_force;
    if (i == middle) {
      out.regime = d.regime;
      out.plug_fraction = d.drop.plug_fraction;
    }
  }
  const MixedModeDrop plain = annulus_mixed_mode(
      g, GapRheology{0.0, fluid.viscosity, fluid.flow_index}, wall_velocity, flow);
  out.dp = integrate_samples(x, gradient, 0.0, g.length);
  out.dp_viscous = plain.drop.dp;
  out.dp_yield = out.dp - out.dp_viscous;
  out.wall_force = integrate_samples(x, wall_force, 0.0, g.length);
  out.b_average = integrate_samples(x, b, 0.0, g.length) / g.length;
  return out;
}

ShearTorque drum_in_field(const DrumGeometry& g, const GapFieldSamples& field, const Fluid& fluid,
                          double speed) {
  validate(g);
  check_field_samples(field, 0.0, g.length, "drum gap field");
  const auto& z = field.position;
  const std::vector<double> b = sample_magnitudes(field.b);
  const DrumGeometry unit{g.r_in, g.r_out, 1.0};
  std::vector<double> torque(z.size()), breakaway(z.size()), yielded(z.size());
  for (std::size_t i = 0; i < z.size(); ++i) {
    const ShearTorque t = drum_torque(
        unit, GapRheology{fluid.yield_stress(b[i]), fluid.viscosity, fluid.flow_index}, speed);
    torque[i] = t.torque;
    breakaway[i] = t.breakaway_torque;
    yielded[i] = t.yielded_fraction;
  }
  ShearTorque out = drum_torque(g, GapRheology{0.0, fluid.viscosity, fluid.flow_index}, speed);
  out.torque = integrate_samples(z, torque, 0.0, g.length);
  out.torque_yield = out.torque - out.torque_viscous;
  out.breakaway_torque = integrate_samples(z, breakaway, 0.0, g.length);
  out.yielded_fraction = integrate_samples(z, yielded, 0.0, g.length) / g.length;
  out.yield_radius = 0.0;  // varies along the drum
  return out;
}

ShearTorque disc_in_field(const DiscGeometry& g, const GapFieldSamples& field, const Fluid& fluid,
                          double speed) {
  validate(g);
  check_field_samples(field, g.r_in, g.r_out, "disc gap field");
  const std::vector<double> b = sample_magnitudes(field.b);
  return disc_torque(
      g, [&](double r) { return fluid.yield_stress(interpolate_samples(field.position, b, r)); },
      fluid.viscosity, fluid.flow_index, speed);
}

}  // namespace rheomag::fluid
