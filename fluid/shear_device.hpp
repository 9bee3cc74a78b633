#pragma once
// `rheomag shear` as a library call: the torque of one shear-mode device (drum or disc) at a
// yield stress and speed, and that result as a JSON document and as a text report.

#include <string>

#include "core/enum_names.hpp"
#include "fluid/shear_mode.hpp"

namespace rheomag::fluid {

/// The shear-mode device of `rheomag shear`.
enum class ShearKind { drum, disc };

/// Text names of ShearKind (CLI, JSON).
inline constexpr auto kShearKindNames =
    enum_names<ShearKind>({{ShearKind::drum, "drum"}, {ShearKind::disc, "disc"}});

/// One device and its speed (SI): a drum reads r_in, r_out, length; a disc r_in, r_out, gap,
/// faces.
struct ShearDeviceInput {
  ShearKind kind = ShearKind::drum;
  double r_in = 0, r_out = 0, length = 0, gap = 0;
  int faces = 2;
  double tau_y = 0, viscosity = 0, flow_index = 1.0, speed = 0;
};

/// The torque of `input`'s device; InputError for bad dimensions or fluid.
ShearTorque shear_device_torque(const ShearDeviceInput& input);

/// The JSON document of `rheomag shear --json`, one line with 12 significant digits.
std::string shear_device_json(const ShearDeviceInput& input, const ShearTorque& t);

/// The text report of `rheomag shear`.
std::string shear_device_text(const ShearDeviceInput& input, const ShearTorque& t);

}  // namespace rheomag::fluid
