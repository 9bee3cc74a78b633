#pragma once
// Gap pressure drop in a non-uniform magnetic field: dp/ds integrated along the gap with the
// local yield stress tau_y(B(s)) from flux-density samples on the gap's mid-line (e.g. the FE
// field), next to the "one average B" shortcut so users can see the difference.

#include <vector>

#include "fluid/field_samples.hpp"
#include "fluid/fluid.hpp"
#include "fluid/gap.hpp"

namespace rheomag::fluid {

/// A gap's pressure drop both ways.
struct FieldCoupledDrop {
  GapPressureDrop integrated;  ///< int dp/ds ds with the local tau_y(B(s)) (trapezoid on samples)
  GapPressureDrop average_b;   ///< uniform tau_y(B_avg) over the whole gap
  double b_average = 0.0;      ///< position-weighted mean of |B| over the samples [T]
};

/// Annular gap (exact curved-annulus law locally); samples must lie in [0, length].
FieldCoupledDrop annular_gap_in_field(const AnnulusGeometry& g, const GapFieldSamples& field,
                                      const Fluid& fluid, double flow);

/// Radial gap (exact local slit law of width 2 pi r); samples must lie in [r_in, r_out].
FieldCoupledDrop radial_gap_in_field(const RadialGeometry& g, const GapFieldSamples& field,
                                     const Fluid& fluid, double flow);

}  // namespace rheomag::fluid
