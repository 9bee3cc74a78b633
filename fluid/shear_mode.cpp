// Shear-mode torque (docs/fluid.md, "Shear mode").
//
// Drum. In steady Couette flow between coaxial cylinders the torque per length is the same on
// every cylindrical surface, so the shear stress falls as tau(r) = T / (2 pi L r^2). The fluid
// yields where tau > tau_y, i.e. inside the yield radius r_y = sqrt(T / (2 pi L tau_y)); beyond it
// (r_y < r_out) it rests against the fixed cylinder (partial yielding). With the angular
// velocity w(r), the shear rate is -r dw/dr = ((tau - tau_y)/K)^(1/n) where yielded, and
//   omega = int_{r_in}^{min(r_y, r_out)} ((tau(r) - tau_y)/K)^(1/n) dr / r.
// Bingham (n = 1), with rho = r_y / r_in:
//   partial yielding    mu omega / tau_y = (rho^2 - 1)/2 - ln rho,   T = 2 pi L tau_y r_y^2,
//   fully yielded       T = 4 pi L (mu omega + tau_y ln(r_out/r_in)) / (1/r_in^2 - 1/r_out^2)
// (the Reiner-Riwlin equation; R. B. Bird, G. C. Dai, B. J. Yarusso, Rev. Chem. Eng. 1 (1983)
// 1-70). Herschel-Bulkley: the same integral by tanh-sinh quadrature, T by bracketed search.
// Power-law torque (tau_y = 0): T = 2 pi L K [2 m omega / (r_in^-2m - r_out^-2m)]^n, m = 1/n.
//
// Disc. Between a disc rotating at omega and a fixed face a gap h away (creeping torsional flow,
// no secondary flow), u_theta = omega r z / h, so the shear rate r omega / h is > 0 at every
// r > 0: the fluid is fully yielded for any omega != 0 and tau(r) = tau_y(r) + K (r omega/h)^n.
//   T = N 2 pi int r^2 tau dr = N 2 pi [tau_y (r_out^3 - r_in^3)/3 + K (omega/h)^n
//       (r_out^(n+3) - r_in^(n+3))/(n+3)]   (uniform tau_y; n = 1 gives the familiar
//       N 2 pi [tau_y (Ro^3 - Ri^3)/3 + mu omega (Ro^4 - Ri^4)/(4 h)]).

#include "fluid/shear_mode.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "core/error.hpp"

namespace rheomag::fluid {

namespace {

constexpr double kPi = std::numbers::pi;
/// Iteration cap of the shear-mode root searches.
constexpr boost::uintmax_t kShearRootIterations = 200;

void require(bool ok, const char* what, double value) {
  if (!ok) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "%s, got %g", what, value);
    throw InputError(buf);
  }
}

void validate_rheology(const GapRheology& f, double speed) {
  require(std::isfinite(f.tau_y) && f.tau_y >= 0.0, "yield stress must be a finite number >= 0 Pa",
          f.tau_y);
  require(std::isfinite(f.consistency) && f.consistency > 0.0,
          "viscosity (consistency K) must be a finite number > 0", f.consistency);
  require(f.flow_index >= 0.1 && f.flow_index <= 3.0,
          "Herschel-Bulkley flow index n must be in [0.1, 3]", f.flow_index);
  require(std::isfinite(speed), "speed must be a finite number (rad/s, either sign)", speed);
}

/// Power-law (tau_y = 0) drum torque at speed |omega| > 0.
double drum_power_law_torque(const DrumGeometry& g, double consistency, double n, double omega) {
  const double m = 1.0 / n;
  const double span = std::pow(g.r_in, -2.0 * m) - std::pow(g.r_out, -2.0 * m);
  return 2.0 * kPi * g.length * consistency * std::pow(2.0 * m * omega / span, n);
}

/// Bingham drum torque at speed omega > 0 (closed form above).
double drum_bingham_torque(const DrumGeometry& g, double tau_y, double mu, double omega,
                           double& yield_radius) {
  const double ln_ratio = std::log(g.r_out / g.r_in);
  const double inv_sq = (g.r_out - g.r_in) * (g.r_out + g.r_in) /
                        (g.r_in * g.r_in * g.r_out * g.r_out);  // 1/r_in^2 - 1/r_out^2
  const double full = 4.0 * kPi * g.length * (mu * omega + tau_y * ln_ratio) / inv_sq;
  if (tau_y == 0.0) {
    yield_radius = g.r_out;
    return full;
  }
  // Speed at which the yield radius reaches r_out: mu omega_c / tau_y = (rho^2 - 1)/2 - ln rho.
  auto speed_of = [](double e) {  // (rho^2 - 1)/2 - ln rho with rho = 1 + e
    return e - std::log1p(e) + 0.5 * e * e;
  };
  const double e_out = (g.r_out - g.r_in) / g.r_in;
  const double target = mu * omega / tau_y;
  if (target >= speed_of(e_out)) {
    yield_radius = g.r_out;
    return full;
  }
  auto f = [&](double e) { return speed_of(e) - target; };
  boost::uintmax_t iterations = kShearRootIterations;
  auto [a, b] = boost::math::tools::toms748_solve(
      f, 0.0, e_out, -target, f(e_out), boost::math::tools::eps_tolerance<double>(50), iterations);
  if (iterations >= kShearRootIterations)
    throw ConvergenceError("drum yield radius did not converge");
  yield_radius = g.r_in * (1.0 + 0.5 * (a + b));
  return 2.0 * kPi * g.length * tau_y * yield_radius * yield_radius;
}

/// Herschel-Bulkley drum torque at speed omega > 0: omega(T) by quadrature, T by bracketing.
double drum_hb_torque(const DrumGeometry& g, const GapRheology& f, double omega,
                      double& yield_radius) {
  const double m = 1.0 / f.flow_index;
  const double t_min = 2.0 * kPi * g.length * f.tau_y * g.r_in * g.r_in;  // breakaway
  boost::math::quadrature::tanh_sinh<double> quad;
  auto edge = [&](double torque) {
    return f.tau_y > 0.0 ? std::min(g.r_out, std::sqrt(torque / (2.0 * kPi * g.length * f.tau_y)))
                         : g.r_out;
  };
  auto speed_at = [&](double torque) {
    const double rc = edge(torque);
    if (!(rc > g.r_in)) return 0.0;
    auto rate = [&](double r) {
      const double excess = torque / (2.0 * kPi * g.length * r * r) - f.tau_y;
      return excess > 0.0 ? std::pow(excess / f.consistency, m) / r : 0.0;
    };
    return quad.integrate(rate, g.r_in, rc, 1e-13);
  };
  // Bracket: the torque of the fully yielded power law plus the breakaway torque over-shoots.
  double lo = t_min, hi = t_min + drum_power_law_torque(g, f.consistency, f.flow_index, omega) +
                          2.0 * kPi * g.length * f.tau_y * g.r_out * g.r_out;
  auto residual = [&](double torque) { return speed_at(torque) - omega; };
  double f_hi = residual(hi);
  for (int k = 0; f_hi < 0.0; ++k) {
    if (k > 200) throw ConvergenceError("drum torque not bracketed");
    lo = hi;
    hi *= 2.0;
    f_hi = residual(hi);
  }
  const double width = hi - lo;
  auto tol = [width](double a, double b) { return std::abs(b - a) <= 1e-14 * width; };
  boost::uintmax_t iterations = kShearRootIterations;
  auto [a, b] =
      boost::math::tools::toms748_solve(residual, lo, hi, residual(lo), f_hi, tol, iterations);
  if (iterations >= kShearRootIterations) throw ConvergenceError("drum torque did not converge");
  const double torque = 0.5 * (a + b);
  yield_radius = edge(torque);
  return torque;
}

}  // namespace

void validate(const DrumGeometry& g) {
  require(std::isfinite(g.r_in) && g.r_in > 0.0, "drum r-in must be a finite number > 0 m", g.r_in);
  require(std::isfinite(g.r_out) && g.r_out > g.r_in,
          "drum r-out must be a finite number > r-in (the gap r-out - r-in must be > 0)", g.r_out);
  require(std::isfinite(g.length) && g.length > 0.0, "drum length must be a finite number > 0 m",
          g.length);
}

void validate(const DiscGeometry& g) {
  require(std::isfinite(g.r_in) && g.r_in >= 0.0, "disc r-in must be a finite number >= 0 m",
          g.r_in);
  require(std::isfinite(g.r_out) && g.r_out > g.r_in, "disc r-out must be a finite number > r-in",
          g.r_out);
  require(std::isfinite(g.gap) && g.gap > 0.0, "disc gap must be a finite number > 0 m", g.gap);
  require(g.faces >= 1, "disc faces must be >= 1", g.faces);
}

ShearTorque drum_torque(const DrumGeometry& g, const GapRheology& fluid, double speed) {
  validate(g);
  validate_rheology(fluid, speed);
  ShearTorque out;
  out.breakaway_torque = 2.0 * kPi * g.length * fluid.tau_y * g.r_in * g.r_in;
  const double omega = std::abs(speed);
  if (omega == 0.0) {
    out.torque = out.torque_yield = out.breakaway_torque;
    out.yield_radius = g.r_in;
    return out;
  }
  double r_y = g.r_out;
  const double torque = fluid.flow_index == 1.0
                            ? drum_bingham_torque(g, fluid.tau_y, fluid.consistency, omega, r_y)
                            : drum_hb_torque(g, fluid, omega, r_y);
  const double viscous = drum_power_law_torque(g, fluid.consistency, fluid.flow_index, omega);
  out.torque = std::copysign(torque, speed);
  out.torque_viscous = std::copysign(viscous, speed);
  out.torque_yield = out.torque - out.torque_viscous;
  out.yield_radius = r_y;
  out.yielded_fraction = (r_y - g.r_in) / (g.r_out - g.r_in);
  return out;
}

ShearTorque disc_torque(const DiscGeometry& g, const GapRheology& fluid, double speed) {
  validate_rheology(fluid, speed);
  validate(g);
  const double tau_y = fluid.tau_y;
  ShearTorque out;
  const double yield = g.faces * 2.0 * kPi * tau_y * (g.r_out - g.r_in) *
                       (g.r_out * g.r_out + g.r_out * g.r_in + g.r_in * g.r_in) / 3.0;
  const double omega = std::abs(speed), n = fluid.flow_index;
  const double viscous = g.faces * 2.0 * kPi * fluid.consistency * std::pow(omega / g.gap, n) *
                         (std::pow(g.r_out, n + 3.0) - std::pow(g.r_in, n + 3.0)) / (n + 3.0);
  out.breakaway_torque = yield;
  out.torque_yield = std::copysign(yield, speed);
  out.torque_viscous = std::copysign(viscous, speed);
  out.torque = out.torque_yield + out.torque_viscous;
  out.yielded_fraction = omega > 0.0 ? 1.0 : 0.0;
  return out;
}

ShearTorque disc_torque(const DiscGeometry& g, const std::function<double(double)>& tau_y_of_r,
                        double consistency, double flow_index, double speed) {
  ShearTorque out = disc_torque(g, GapRheology{0.0, consistency, flow_index}, speed);
  auto integrand = [&](double r) {
    const double tau = tau_y_of_r(r);
    if (!(std::isfinite(tau) && tau >= 0.0))
      throw InputError("disc: yield stress must be finite and >= 0 at every radius");
    return r * r * tau;
  };
  double error = 0.0;
  const double yield = g.faces * 2.0 * kPi *
                       boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
                           integrand, g.r_in, g.r_out, 20, 1e-10, &error);
  out.breakaway_torque = yield;
  out.torque_yield = speed == 0.0 ? yield : std::copysign(yield, speed);
  out.torque = out.torque_yield + out.torque_viscous;
  return out;
}

}  // namespace rheomag::fluid
