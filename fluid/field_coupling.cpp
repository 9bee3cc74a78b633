// Field-coupled gap flow. The field varies slowly compared with the gap (lubrication), so each
// position s along the gap is a fully developed Bingham flow at the local yield stress
// tau_y(B(s)):  dp = int_0^L G(tau_y(B(s))) ds, with G the exact annulus gradient
// (annulus_bingham.cpp) or, for a radial gap, the exact local slit law of width 2 pi r
// (radial_bingham.cpp). The field is known only at the samples (the FE mid-line field), so the
// integral is the trapezoidal rule over the samples, with dp/ds held constant from the first and
// last sample to the gap ends. The viscous (tau_y = 0) part is integrated exactly.
// "One average B": B_avg = (1/L) int B ds (same trapezoid), tau_y(B_avg) uniform over the gap:
// the single-flux-density estimate of paper 000 section 2.2.

#include "fluid/field_coupling.hpp"

#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "fluid/annulus_bingham.hpp"
#include "fluid/radial_bingham.hpp"
#include "fluid/slit_bingham.hpp"

namespace rheomag::fluid {

FieldCoupledDrop annular_gap_in_field(const AnnulusGeometry& g, const GapFieldSamples& field,
                                      const Fluid& fluid, double flow) {
  validate(g);
  validate_flow(0.0, fluid.viscosity, flow);
  check_field_samples(field, 0.0, g.length, "annular gap field");
  const auto& x = field.position;
  const std::vector<double> b = sample_magnitudes(field.b);
  const AnnulusGeometry unit{g.gap, g.radius, 1.0};  // dp of unit length = the gradient
  std::vector<double> gradient(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    gradient[i] = annulus_bingham(unit, fluid.yield_stress(b[i]), fluid.viscosity, flow).dp;
  FieldCoupledDrop out;
  out.b_average = integrate_samples(x, b, 0.0, g.length) / g.length;
  out.average_b = annulus_bingham(g, fluid.yield_stress(out.b_average), fluid.viscosity, flow);
  const GapPressureDrop middle = annulus_bingham(
      g, fluid.yield_stress(interpolate_samples(x, b, 0.5 * g.length)), fluid.viscosity, flow);
  out.integrated.dp = integrate_samples(x, gradient, 0.0, g.length);
  out.integrated.dp_viscous = out.average_b.dp_viscous;
  out.integrated.dp_yield = out.integrated.dp - out.integrated.dp_viscous;
  out.integrated.plug_fraction = middle.plug_fraction;
  out.integrated.bingham_number = middle.bingham_number;
  return out;
}

FieldCoupledDrop radial_gap_in_field(const RadialGeometry& g, const GapFieldSamples& field,
                                     const Fluid& fluid, double flow) {
  validate(g);
  validate_flow(0.0, fluid.viscosity, flow);
  check_field_samples(field, g.r_in, g.r_out, "radial gap field");
  const auto& r = field.position;
  const std::vector<double> b = sample_magnitudes(field.b);
  // Yield part of dp/dr = c(Bi(r)) tau_y(r) / h at each sample (viscous part exact below).
  std::vector<double> yield_gradient(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) {
    const double tau = fluid.yield_stress(b[i]);
    const double bi =
        bingham_number(tau, fluid.viscosity, g.gap, 2.0 * std::numbers::pi * r[i], flow);
    yield_gradient[i] = tau == 0.0 ? 0.0 : slit_yield_coefficient(bi) * tau / g.gap;
  }
  FieldCoupledDrop out;
  out.b_average = integrate_samples(r, b, g.r_in, g.r_out) / (g.r_out - g.r_in);
  out.average_b = radial_bingham(g, fluid.yield_stress(out.b_average), fluid.viscosity, flow);
  const double r_mean = 0.5 * (g.r_in + g.r_out);
  const double tau_mean = fluid.yield_stress(interpolate_samples(r, b, r_mean));
  out.integrated.dp_viscous = out.average_b.dp_viscous;
  out.integrated.dp_yield = integrate_samples(r, yield_gradient, g.r_in, g.r_out);
  out.integrated.dp = out.integrated.dp_viscous + out.integrated.dp_yield;
  out.integrated.bingham_number =
      bingham_number(tau_mean, fluid.viscosity, g.gap, 2.0 * std::numbers::pi * r_mean, flow);
  out.integrated.plug_fraction = slit_plug_fraction(out.integrated.bingham_number);
  return out;
}

}  // namespace rheomag::fluid
