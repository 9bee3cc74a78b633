#pragma once
// Gap geometries and the pressure-drop result shared by every gap-flow model (SI units).

namespace rheomag::fluid {

/// Pressure drop across one gap at one flow rate, split into viscous and yield parts.
struct GapPressureDrop {
  double dp = 0.0;              ///< total pressure drop [Pa]
  double dp_viscous = 0.0;      ///< Newtonian (tau_y = 0) pressure drop at the same Q [Pa]
  double dp_yield = 0.0;        ///< dp - dp_viscous [Pa]
  double plug_fraction = 0.0;   ///< plug thickness / gap (radial: at the mean radius)
  double bingham_number = 0.0;  ///< tau_y h / (mu V_mean) (radial: at the mean radius)
};

/// A parallel-plate slit: gap h between the plates, width b across the flow, length L along it.
struct SlitGeometry {
  double gap = 0.0;     ///< h [m]
  double width = 0.0;   ///< b [m]
  double length = 0.0;  ///< L [m]
};

/// An annular gap for axial flow: radial clearance h about the mean radius R, axial length L.
struct AnnulusGeometry {
  double gap = 0.0;     ///< h = R_out - R_in [m]
  double radius = 0.0;  ///< mean radius R = (R_in + R_out)/2 [m]
  double length = 0.0;  ///< L [m]
  /// Inner wall radius R - h/2 [m].
  double inner() const { return radius - 0.5 * gap; }
  /// Outer wall radius R + h/2 [m].
  double outer() const { return radius + 0.5 * gap; }
};

/// A radial (disk) gap of axial clearance h between radii r_in and r_out.
struct RadialGeometry {
  double gap = 0.0;    ///< h [m]
  double r_in = 0.0;   ///< inner radius [m]
  double r_out = 0.0;  ///< outer radius [m]
};

/// Throws InputError unless gap, width and length are finite and > 0.
void validate(const SlitGeometry& g);
/// Throws InputError unless gap, radius, length > 0 and the gap fits (h < 2R).
void validate(const AnnulusGeometry& g);
/// Throws InputError unless gap > 0 and 0 < r_in < r_out.
void validate(const RadialGeometry& g);
/// Throws InputError unless tau_y >= 0, viscosity > 0 and flow > 0 (all finite).
void validate_flow(double tau_y, double viscosity, double flow);

}  // namespace rheomag::fluid
