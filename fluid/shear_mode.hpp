#pragma once
// Shear-mode MR devices: exact Bingham / Herschel-Bulkley torque of a drum (Couette flow between
// coaxial cylinders, inner one rotating, with partial yielding) and of a disc (torsional flow in
// thin gaps between a rotating disc and fixed housing faces, tau_y may vary with radius).

#include <functional>

#include "fluid/mixed_mode.hpp"

namespace rheomag::fluid {

/// Coaxial cylinders: the inner one (radius r_in) rotates, the outer one (r_out) is fixed.
struct DrumGeometry {
  double r_in = 0.0;    ///< rotating cylinder radius [m]
  double r_out = 0.0;   ///< fixed cylinder radius [m]
  double length = 0.0;  ///< axial length of the fluid annulus [m]
};

/// A disc of radii r_in..r_out rotating at `gap` from `faces` fixed faces (1 or 2 usually).
struct DiscGeometry {
  double r_in = 0.0;   ///< inner radius of the wetted, sheared ring [m]
  double r_out = 0.0;  ///< outer radius [m]
  double gap = 0.0;    ///< axial gap between disc and housing face [m]
  int faces = 2;       ///< number of sheared faces
};

/// Torque of a shear-mode device at one speed, split like GapPressureDrop.
struct ShearTorque {
  double torque = 0.0;            ///< resisting torque on the rotor, sign of the speed [N m]
  double torque_viscous = 0.0;    ///< Newtonian / power-law (tau_y = 0) torque at this speed
  double torque_yield = 0.0;      ///< torque - torque_viscous
  double breakaway_torque = 0.0;  ///< torque as speed -> 0+ (the holding torque) [N m]
  double yielded_fraction = 0.0;  ///< drum: yielded radial fraction of the gap; disc: 1 (0 at rest)
  double yield_radius = 0.0;      ///< drum: radius where the stress falls to tau_y (r_out if all
                                  ///< yielded) [m]; disc: 0
};

/// Throws InputError unless 0 < r_in < r_out and length > 0 (all finite).
void validate(const DrumGeometry& g);
/// Throws InputError unless 0 <= r_in < r_out, gap > 0 and faces >= 1.
void validate(const DiscGeometry& g);

/// Exact Couette flow of a Herschel-Bulkley fluid between the drum's cylinders at angular speed
/// `speed` [rad/s] (either sign); speed 0 gives the breakaway torque.
ShearTorque drum_torque(const DrumGeometry& g, const GapRheology& fluid, double speed);

/// Disc torque with a uniform yield stress.
ShearTorque disc_torque(const DiscGeometry& g, const GapRheology& fluid, double speed);

/// Disc torque with tau_y(r) [Pa] varying with radius r [m] (e.g. from an FE field):
/// T = faces 2 pi int r^2 (tau_y(r) + K (r |omega| / h)^n) dr, the yield part by adaptive
/// Gauss-Kronrod quadrature.
ShearTorque disc_torque(const DiscGeometry& g, const std::function<double(double)>& tau_y_of_r,
                        double consistency, double flow_index, double speed);

}  // namespace rheomag::fluid
