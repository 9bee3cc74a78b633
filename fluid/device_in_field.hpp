#pragma once
// Damper and brake gaps in a non-uniform magnetic field: the mixed-mode annular gap of a piston
// and the shear-mode drum and disc, each with the local yield stress tau_y(B(s)) from mid-line
// flux-density samples (e.g. the FE field), locally fully developed.

#include "fluid/field_samples.hpp"
#include "fluid/fluid.hpp"
#include "fluid/mixed_mode.hpp"
#include "fluid/shear_mode.hpp"

namespace rheomag::fluid {

/// A moving-wall annular gap in a sampled field.
struct MovingGapDrop {
  double dp = 0.0;          ///< int dp/ds ds with the local tau_y(B(s)) [Pa] (may be < 0)
  double dp_viscous = 0.0;  ///< the tau_y = 0 drop at the same flow and wall velocity [Pa]
  double dp_yield = 0.0;    ///< dp - dp_viscous [Pa]
  double wall_force = 0.0;  ///< shear force of the fluid on the moving wall along the flow [N]
  double b_average = 0.0;   ///< position-weighted mean |B| over the samples [T]
  MixedRegime regime = MixedRegime::fully_yielded;  ///< at the sample nearest the gap's middle
  double plug_fraction = 0.0;                       ///< there
};

/// Annular gap whose inner wall moves at `wall_velocity` along the flow, `flow` counted in the
/// outer wall's frame; samples at axial positions in [0, length]; Herschel-Bulkley with the
/// fluid's flow index.
MovingGapDrop moving_annular_gap_in_field(const AnnulusGeometry& g, const GapFieldSamples& field,
                                          const Fluid& fluid, double wall_velocity, double flow);

/// Drum whose fluid annulus sees tau_y(B(z)), samples at axial positions in [0, length]: the
/// torque per length of each slice integrated along z (trapezoid over the samples).
ShearTorque drum_in_field(const DrumGeometry& g, const GapFieldSamples& field, const Fluid& fluid,
                          double speed);

/// One sheared disc face with tau_y(B(r)), samples at radii in [r_in, r_out] (linear between).
ShearTorque disc_in_field(const DiscGeometry& g, const GapFieldSamples& field, const Fluid& fluid,
                          double speed);

}  // namespace rheomag::fluid
