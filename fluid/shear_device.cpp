#include "fluid/shear_device.hpp"

#include "core/format_text.hpp"

namespace rheomag::fluid {

ShearTorque shear_device_torque(const ShearDeviceInput& o) {
  const GapRheology fluid{o.tau_y, o.viscosity, o.flow_index};
  return o.kind == ShearKind::drum
             ? drum_torque(DrumGeometry{o.r_in, o.r_out, o.length}, fluid, o.speed)
             : disc_torque(DiscGeometry{o.r_in, o.r_out, o.gap, o.faces}, fluid, o.speed);
}

std::string shear_device_json(const ShearDeviceInput& o, const ShearTorque& t) {
  return format_text(
      "{\"kind\": \"%s\", \"speed\": %.12g, \"torque\": %.12g, \"torque_yield\": %.12g, "
      "\"torque_viscous\": %.12g, \"breakaway_torque\": %.12g, \"yielded_fraction\": %.12g, "
      "\"yield_radius\": %.12g}\n",
      std::string(kShearKindNames.name(o.kind)).c_str(), o.speed, t.torque, t.torque_yield,
      t.torque_viscous, t.breakaway_torque, t.yielded_fraction, t.yield_radius);
}

std::string shear_device_text(const ShearDeviceInput& o, const ShearTorque& t) {
  std::string out = format_text("%s, speed %g rad/s\n",
                                std::string(kShearKindNames.name(o.kind)).c_str(), o.speed);
  out += format_text("  torque               T             = %.6g N m\n", t.torque);
  out += format_text("  viscous part         T_viscous     = %.6g N m\n", t.torque_viscous);
  out += format_text("  yield part           T_yield       = %.6g N m\n", t.torque_yield);
  out += format_text("  breakaway torque     T(0+)         = %.6g N m\n", t.breakaway_torque);
  out += format_text("  yielded fraction                   = %.6g\n", t.yielded_fraction);
  if (o.kind == ShearKind::drum)
    out += format_text("  yield radius         r_y           = %.6g m\n", t.yield_radius);
  return out;
}

}  // namespace rheomag::fluid
