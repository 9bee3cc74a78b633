// Exact Bingham slit flow. With the pressure gradient G = dp/L the shear stress is linear across
// the gap and the plug (|tau| < tau_y) has thickness delta h = 2 tau_y / G. The Buckingham-Reiner
// flow rate of a slit, Q = b h^3 G / (12 mu) (1 - 3 delta / 2 + delta^3 / 2), with
// V = Q / (b h) and Bi = tau_y h / (mu V) gives the plug-fraction cubic
//     delta^3 - 3 (1 + 4 / Bi) delta + 2 = 0,  delta in (0, 1],
// and dp = 2 tau_y L / (delta h) = 12 mu Q L / (b h^3) + c tau_y L / h with c = 2/delta - 12/Bi.
// Eliminating 12/Bi with the cubic gives c = 3 - delta^2 exactly, which has no cancellation as
// Bi -> 0 (delta ~ Bi/6, c -> 3) or Bi -> inf (delta ~ 1 - 2/sqrt(Bi), c -> 2).
// References: R. W. Phillips, PhD thesis, UC Berkeley (1969); G. M. Kamath, M. K. Hurt,
// N. M. Wereley, "Analysis and testing of Bingham plastic behavior in semi-active
// electrorheological fluid dampers", Smart Mater. Struct. 5 (1996) 576-590 (same cubic).
// Paper-000 approximation: Imaduddin et al., Micromachines 16 (2025) 144, eqs. (2)-(3).

#include "fluid/slit_bingham.hpp"

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "fluid/newtonian.hpp"

namespace rheomag::fluid {

double bingham_number(double tau_y, double viscosity, double gap, double width, double flow) {
  const double mean_velocity = flow / (width * gap);
  return tau_y * gap / (viscosity * mean_velocity);
}

double slit_plug_fraction(double bi) {
  if (std::isnan(bi) || bi < 0.0) throw InputError("Bingham number must be >= 0");
  if (bi == 0.0) return 0.0;
  if (std::isinf(bi)) return 1.0;
  // With delta^3 - 3 delta + 2 = (1 - delta)^2 (delta + 2), Bi times the cubic is
  // g(delta) = Bi (1 - delta)^2 (delta + 2) - 12 delta: no 1/Bi overflow, strictly decreasing
  // on [0, 1] with g(0) = 2 Bi > 0 and g(1) = -12 < 0, so exactly one root there.
  auto g = [bi](double d) { return bi * (1.0 - d) * (1.0 - d) * (d + 2.0) - 12.0 * d; };
  boost::uintmax_t iterations = 300;
  auto [lo, hi] = boost::math::tools::toms748_solve(
      g, 0.0, 1.0, 2.0 * bi, -12.0, boost::math::tools::eps_tolerance<double>(52), iterations);
  if (iterations >= 300)
    throw ConvergenceError("slit plug-fraction cubic did not converge at Bi = " +
                           std::to_string(bi));
  return 0.5 * (lo + hi);
}

double slit_yield_coefficient(double bi) {
  const double delta = slit_plug_fraction(bi);
  return 3.0 - delta * delta;
}

double paper000_yield_coefficient(double bi) {
  if (std::isinf(bi)) return 2.07;
  return 2.07 + 12.0 / (12.0 + 0.4 * bi);
}

GapPressureDrop slit_bingham(const SlitGeometry& g, double tau_y, double viscosity, double flow) {
  validate(g);
  validate_flow(tau_y, viscosity, flow);
  GapPressureDrop out;
  out.bingham_number = bingham_number(tau_y, viscosity, g.gap, g.width, flow);
  out.plug_fraction = slit_plug_fraction(out.bingham_number);
  out.dp_viscous = slit_poiseuille_dp(g, viscosity, flow);
  out.dp_yield = (3.0 - out.plug_fraction * out.plug_fraction) * tau_y * g.length / g.gap;
  out.dp = out.dp_viscous + out.dp_yield;
  return out;
}

GapPressureDrop annulus_slit_bingham(const AnnulusGeometry& g, double tau_y, double viscosity,
                                     double flow) {
  validate(g);
  return slit_bingham(SlitGeometry{g.gap, 2.0 * std::numbers::pi * g.radius, g.length}, tau_y,
                      viscosity, flow);
}

GapPressureDrop annulus_paper000(const AnnulusGeometry& g, double tau_y, double viscosity,
                                 double flow) {
  validate(g);
  validate_flow(tau_y, viscosity, flow);
  const double d = g.gap, r = g.radius, l = g.length;
  GapPressureDrop out;
  out.bingham_number = bingham_number(tau_y, viscosity, d, 2.0 * std::numbers::pi * r, flow);
  out.plug_fraction = slit_plug_fraction(out.bingham_number);
  // Eq. (3) exactly as printed: c = 2.07 + 12 Q eta / (12 Q eta + 0.8 pi R d^2 tau_y).
  const double c =
      2.07 + 12.0 * flow * viscosity /
                 (12.0 * flow * viscosity + 0.8 * std::numbers::pi * r * d * d * tau_y);
  // Eq. (2): viscous term 6 eta Q L / (pi d^3 R) = the slit term with b = 2 pi R.
  out.dp_viscous = 6.0 * viscosity * flow * l / (std::numbers::pi * d * d * d * r);
  out.dp_yield = c * tau_y * l / d;
  out.dp = out.dp_viscous + out.dp_yield;
  return out;
}

}  // namespace rheomag::fluid
