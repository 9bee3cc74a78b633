// Exact axial Bingham flow in an annulus R_i < r < R_o (Fredrickson & Bird, "Non-Newtonian flow
// in annuli", Ind. Eng. Chem. 50 (1958) 347-352; Bird, Dai & Yarusso, Rev. Chem. Eng. 1 (1983)).
// With G = -dp/dz the shear stress is tau(r) = -(G/2)(r - lambda^2/r). The plug r1 <= r <= r2 is
// where |tau| <= tau_y: tau(r1) = tau_y and tau(r2) = -tau_y give r2 - r1 = 2 tau_y / G and
// lambda^2 = r1 r2. Velocities (no slip at both walls):
//   inner  mu u(r) = -(G/4)(r^2 - Ri^2) + (G lambda^2/2) ln(r/Ri) - tau_y (r - Ri),
//   outer  mu u(r) = -(G/4)(r^2 - Ro^2) + (G lambda^2/2) ln(r/Ro) + tau_y (r - Ro),
// and the plug velocity is continuous: u_inner(r1) = u_outer(r2), which fixes r1 (solved here
// by bracketed root finding). The flow rate by parts, Q = -pi int r^2 u'(r) dr, is
//   Q = (pi G / 2 mu) { [(r1^4 - Ri^4)/4 - lambda^2 (r1^2 - Ri^2)/2 + t (r1^3 - Ri^3)/3]
//                     + [(Ro^4 - r2^4)/4 - lambda^2 (Ro^2 - r2^2)/2 - t (Ro^3 - r2^3)/3] },
// t = r2 - r1. For a given Q the plug fraction delta = t / h is found by a second bracketed
// root search (Q decreases monotonically from infinity at delta -> 0 to 0 at delta = 1), started
// from the slit solution. Differences of powers are factored to avoid cancellation.

#include "fluid/annulus_bingham.hpp"

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "fluid/newtonian.hpp"
#include "fluid/slit_bingham.hpp"

namespace rheomag::fluid {

namespace {

/// Iteration cap of the plug-position root search.
constexpr boost::uintmax_t kPlugRootIterations = 300;

/// mu (u_inner(r1) - u_outer(r2)) / G with r1 = Ri + x, r2 = r1 + t.
double plug_velocity_mismatch(double ri, double ro, double t, double x) {
  const double r1 = ri + x, r2 = r1 + t, y = ro - r2;
  const double lambda2 = r1 * r2;
  const double inner = -x * (2.0 * ri + x) / 4.0 + 0.5 * lambda2 * std::log1p(x / ri) - 0.5 * t * x;
  const double outer = y * (2.0 * ro - y) / 4.0 + 0.5 * lambda2 * std::log1p(-y / ro) - 0.5 * t * y;
  return inner - outer;
}

}  // namespace

AnnulusPlug annulus_plug(const AnnulusGeometry& g, double tau_y, double viscosity,
                         double plug_fraction) {
  validate(g);
  validate_flow(tau_y, viscosity, 1.0);
  if (!(tau_y > 0.0)) throw InputError("annulus_plug needs tau_y > 0");
  if (!(plug_fraction > 0.0 && plug_fraction <= 1.0))
    throw InputError("annulus plug fraction must be in (0, 1]");
  const double ri = g.inner(), ro = g.outer(), h = g.gap;
  const double t = plug_fraction * h;
  AnnulusPlug plug;
  plug.gradient = 2.0 * tau_y / t;
  const double span = h - t;  // the plug's inner edge lies in [Ri, Ri + span]
  double x = 0.0;
  if (span > 0.0) {
    auto f = [&](double s) { return plug_velocity_mismatch(ri, ro, t, s); };
    const double f_lo = f(0.0), f_hi = f(span);
    if (!(f_lo <= 0.0 && f_hi >= 0.0))
      throw ConvergenceError(
          "annulus plug position not bracketed (delta = " + std::to_string(plug_fraction) + ")");
    boost::uintmax_t iterations = kPlugRootIterations;
    auto [lo, hi] = boost::math::tools::toms748_solve(
        f, 0.0, span, f_lo, f_hi, boost::math::tools::eps_tolerance<double>(50), iterations);
    if (iterations >= kPlugRootIterations)
      throw ConvergenceError("annulus plug position did not converge");
    x = 0.5 * (lo + hi);
  }
  const double r1 = ri + x, r2 = r1 + t, y = ro - r2;
  const double lambda2 = r1 * r2;
  // Factored differences: a^n - b^n with a - b = x (inner) or y (outer).
  const double inner = x * (r1 + ri) * (r1 * r1 + ri * ri) / 4.0 - lambda2 * x * (r1 + ri) / 2.0 +
                       t * x * (r1 * r1 + r1 * ri + ri * ri) / 3.0;
  const double outer = y * (ro + r2) * (ro * ro + r2 * r2) / 4.0 - lambda2 * y * (ro + r2) / 2.0 -
                       t * y * (ro * ro + ro * r2 + r2 * r2) / 3.0;
  plug.inner = r1;
  plug.outer = r2;
  plug.flow = std::numbers::pi * plug.gradient / (2.0 * viscosity) * (inner + outer);
  return plug;
}

GapPressureDrop annulus_bingham(const AnnulusGeometry& g, double tau_y, double viscosity,
                                double flow) {
  validate(g);
  validate_flow(tau_y, viscosity, flow);
  GapPressureDrop out;
  out.dp_viscous = annulus_poiseuille_dp(g, viscosity, flow);
  out.bingham_number =
      bingham_number(tau_y, viscosity, g.gap, 2.0 * std::numbers::pi * g.radius, flow);
  if (tau_y == 0.0) {
    out.dp = out.dp_viscous;
    return out;
  }
  auto excess = [&](double delta) { return annulus_plug(g, tau_y, viscosity, delta).flow - flow; };
  // Bracket from the slit solution: the flow excess is > 0 at small delta and -Q at delta = 1.
  double lo = 0.5 * slit_plug_fraction(out.bingham_number);
  double f_lo = excess(lo);
  for (int k = 0; f_lo <= 0.0; ++k) {
    if (k > 200) throw ConvergenceError("annulus plug fraction could not be bracketed");
    lo *= 0.5;
    f_lo = excess(lo);
  }
  boost::uintmax_t iterations = kPlugRootIterations;
  auto [a, b] = boost::math::tools::toms748_solve(
      excess, lo, 1.0, f_lo, -flow, boost::math::tools::eps_tolerance<double>(50), iterations);
  if (iterations >= kPlugRootIterations)
    throw ConvergenceError(
        "annulus plug fraction did not converge (Bi = " + std::to_string(out.bingham_number) + ")");
  out.plug_fraction = 0.5 * (a + b);
  out.dp = 2.0 * tau_y * g.length / (out.plug_fraction * g.gap);
  out.dp_yield = out.dp - out.dp_viscous;
  return out;
}

}  // namespace rheomag::fluid
