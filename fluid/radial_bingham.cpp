// Radial (disk) gap of clearance h between r_in and r_out. Locally the gap is a slit of width
// b = 2 pi r with mean velocity V(r) = Q / (2 pi r h), so Bi(r) = 2 pi r h^2 tau_y / (mu Q) and
//   dp/dr = 6 mu Q / (pi r h^3) + c(Bi(r)) tau_y(r) / h            (creeping flow, no inertia)
// with the exact slit coefficient c = 3 - delta(Bi)^2 (see slit_bingham.cpp). The viscous part
// integrates to 6 mu Q ln(r_out/r_in) / (pi h^3); the yield part is integrated numerically.
// The lubrication (locally fully developed) assumption needs h << r_out - r_in; inertia
// (radial acceleration) is neglected; this local-slit (lubrication) treatment is the usual
// one for radial MR valve gaps, here with the exact rather than an approximate c(Bi).

#include "fluid/radial_bingham.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "fluid/newtonian.hpp"
#include "fluid/slit_bingham.hpp"

namespace rheomag::fluid {

GapPressureDrop radial_bingham(const RadialGeometry& g, double tau_y, double viscosity, double flow,
                               SlitLaw law) {
  validate_flow(tau_y, viscosity, flow);
  return radial_bingham(
      g, [tau_y](double) { return tau_y; }, viscosity, flow, law);
}

GapPressureDrop radial_bingham(const RadialGeometry& g,
                               const std::function<double(double)>& tau_y_of_r, double viscosity,
                               double flow, SlitLaw law) {
  validate(g);
  validate_flow(0.0, viscosity, flow);
  const double h = g.gap;
  auto local_bi = [&](double r, double tau) {
    return bingham_number(tau, viscosity, h, 2.0 * std::numbers::pi * r, flow);
  };
  auto coefficient = [&](double bi) {
    return law == SlitLaw::exact ? slit_yield_coefficient(bi) : paper000_yield_coefficient(bi);
  };
  auto yield_gradient = [&](double r) {
    const double tau = tau_y_of_r(r);
    if (!(std::isfinite(tau) && tau >= 0.0))
      throw InputError("radial gap: yield stress must be finite and >= 0 at every radius");
    return tau == 0.0 ? 0.0 : coefficient(local_bi(r, tau)) * tau / h;
  };
  double error = 0.0;
  const double yield = boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
      yield_gradient, g.r_in, g.r_out, 20, 1e-10, &error);
  GapPressureDrop out;
  out.dp_viscous = radial_poiseuille_dp(g, viscosity, flow);
  out.dp_yield = yield;
  out.dp = out.dp_viscous + out.dp_yield;
  const double r_mean = 0.5 * (g.r_in + g.r_out);
  out.bingham_number = local_bi(r_mean, tau_y_of_r(r_mean));
  out.plug_fraction = slit_plug_fraction(out.bingham_number);
  return out;
}

}  // namespace rheomag::fluid
