// Herschel-Bulkley slit flow. With y measured from the mid-plane the shear stress is tau = G y
// (G = dp/L), the wall stress tau_w = G h / 2 and the plug |y| < tau_y / G. Outside the plug
// gamma_dot = ((tau - tau_y) / K)^(1/n); integrating by parts, q = Q / b = 2 int y gamma_dot dy:
//   Q / b = 2 / (G^2 K^m) [ s^(m+2) / (m+2) + tau_y s^(m+1) / (m+1) ],  s = tau_w - tau_y,
// m = 1/n (derived like the Buckingham-Reiner equation; cf. R. P. Chhabra, J. F. Richardson,
// Non-Newtonian Flow and Applied Rheology, 2nd ed., Butterworth-Heinemann 2008). Q increases
// monotonically with s; the excess wall stress s for a given Q is found by bracketed root finding
// (TOMS 748) on ln Q(s) - ln Q, then dp = 2 tau_w L / h. For n = 1 this is the Buckingham-Reiner
// slit.

#include "fluid/herschel_bulkley.hpp"

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace rheomag::fluid {

namespace {

void validate_hb(double consistency, double flow_index) {
  if (!(std::isfinite(consistency) && consistency > 0.0))
    throw InputError("Herschel-Bulkley consistency K must be a finite number > 0");
  if (!(flow_index >= 0.1 && flow_index <= 3.0))
    throw InputError("Herschel-Bulkley flow index n must be in [0.1, 3]");
}

/// ln(Q / b) at excess wall stress s > 0, computed in logs to avoid overflow of s^(m+2).
double log_flow_per_width(double h, double tau_y, double k, double n, double s) {
  const double m = 1.0 / n, tau_w = tau_y + s;
  const double g = 2.0 * tau_w / h;
  const double bracket = s / (m + 2.0) + tau_y / (m + 1.0);  // times s^(m+1)
  return std::log(2.0) - 2.0 * std::log(g) - m * std::log(k) + (m + 1.0) * std::log(s) +
         std::log(bracket);
}

}  // namespace

double herschel_bulkley_slit_flow(const SlitGeometry& g, double tau_y, double consistency,
                                  double flow_index, double wall_stress) {
  validate(g);
  validate_hb(consistency, flow_index);
  if (!(tau_y >= 0.0)) throw InputError("yield stress must be >= 0");
  const double s = wall_stress - tau_y;
  if (!(s > 0.0)) return 0.0;
  return g.width * std::exp(log_flow_per_width(g.gap, tau_y, consistency, flow_index, s));
}

GapPressureDrop herschel_bulkley_slit(const SlitGeometry& g, double tau_y, double consistency,
                                      double flow_index, double flow) {
  validate(g);
  validate_flow(tau_y, consistency, flow);
  validate_hb(consistency, flow_index);
  const double h = g.gap, n = flow_index, k = consistency;
  const double target = std::log(flow / g.width);
  auto residual = [&](double log_s) {
    return log_flow_per_width(h, tau_y, k, n, std::exp(log_s)) - target;
  };
  // Power-law wall stress (tau_y = 0) at the same Q, also the starting guess: the formula
  // above with tau_y = 0 gives Q/b = h^2 tau_w^m / (2 (m+2) K^m).
  const double m = 1.0 / n;
  const double tau_w_power_law =
      std::pow(2.0 * (m + 2.0) * std::pow(k, m) * (flow / g.width) / (h * h), 1.0 / m);
  double lo = std::log(tau_w_power_law), hi = lo;
  double f_lo = residual(lo), f_hi = f_lo;
  for (int i = 0; f_lo > 0.0; ++i) {
    if (i > 400) throw ConvergenceError("Herschel-Bulkley wall stress not bracketed (low side)");
    hi = lo, f_hi = f_lo;
    lo -= 1.0;
    f_lo = residual(lo);
  }
  for (int i = 0; f_hi < 0.0; ++i) {
    if (i > 400) throw ConvergenceError("Herschel-Bulkley wall stress not bracketed (high side)");
    lo = hi, f_lo = f_hi;
    hi += 1.0;
    f_hi = residual(hi);
  }
  double log_s = f_lo == 0.0 ? lo : hi;
  if (f_lo != 0.0 && f_hi != 0.0) {
    boost::uintmax_t iterations = 300;
    auto [a, b] = boost::math::tools::toms748_solve(
        residual, lo, hi, f_lo, f_hi, boost::math::tools::eps_tolerance<double>(50), iterations);
    if (iterations >= 300) throw ConvergenceError("Herschel-Bulkley wall stress did not converge");
    log_s = 0.5 * (a + b);
  }
  const double s = tau_y == 0.0 ? tau_w_power_law : std::exp(log_s);
  const double tau_w = tau_y + s;
  GapPressureDrop out;
  out.dp = 2.0 * tau_w * g.length / h;
  out.dp_viscous = 2.0 * tau_w_power_law * g.length / h;
  out.dp_yield = out.dp - out.dp_viscous;
  out.plug_fraction = tau_y / tau_w;
  const double mean_velocity = flow / (g.width * h);
  out.bingham_number = tau_y / (k * std::pow(mean_velocity / h, n));
  return out;
}

}  // namespace rheomag::fluid
