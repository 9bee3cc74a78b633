// Newtonian laminar passages. References:
//  - slit: plane Poiseuille flow, Q = b h^3 G / (12 mu);
//  - annulus: Q = pi G / (8 mu) [Ro^4 - Ri^4 - (Ro^2 - Ri^2)^2 / ln(Ro/Ri)]
//    (R. B. Bird, W. E. Stewart, E. N. Lightfoot, Transport Phenomena, 2nd ed., eq. 2.4-17).
//    With Ro,i = R (1 +- e), e = h / (2R), the bracket is R^4 f(e) with
//    f(e) = 8 e (e^2 + (atanh e - e) / atanh e), which has no cancellation as e -> 0
//    (f -> 32 e^3 / 3, the slit limit);
//  - pipe: Hagen-Poiseuille, Q = pi D^4 G / (128 mu);
//  - radial disk: dp/dr = 6 mu Q / (pi r h^3) (slit of width 2 pi r), integrated in r;
//  - minor losses: dp = K rho V^2 / 2 (e.g. Idelchik, Handbook of Hydraulic Resistance).

#include "fluid/newtonian.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace rheomag::fluid {

double atanh_minus_x(double x) {
  if (x >= 0.5) return std::atanh(x) - x;
  // atanh x - x = sum_{k>=1} x^(2k+1) / (2k+1); terms shrink by at least x^2 <= 1/4.
  const double x2 = x * x;
  double power = x * x2, sum = 0.0;
  for (int k = 1; k < 200; ++k) {
    const double term = power / (2 * k + 1);
    sum += term;
    if (term <= 1e-18 * sum) break;
    power *= x2;
  }
  return sum;
}

double slit_poiseuille_dp(const SlitGeometry& g, double viscosity, double flow) {
  validate(g);
  validate_flow(0.0, viscosity, flow);
  return 12.0 * viscosity * flow * g.length / (g.width * g.gap * g.gap * g.gap);
}

double annulus_poiseuille_dp(const AnnulusGeometry& g, double viscosity, double flow) {
  validate(g);
  validate_flow(0.0, viscosity, flow);
  const double e = 0.5 * g.gap / g.radius;
  const double f = 8.0 * e * (e * e + atanh_minus_x(e) / std::atanh(e));
  const double r4 = std::pow(g.radius, 4);
  const double gradient = 8.0 * viscosity * flow / (std::numbers::pi * r4 * f);
  return gradient * g.length;
}

double pipe_poiseuille_dp(double diameter, double length, double viscosity, double flow) {
  validate(SlitGeometry{diameter, 1.0, length});
  validate_flow(0.0, viscosity, flow);
  return 128.0 * viscosity * flow * length / (std::numbers::pi * std::pow(diameter, 4));
}

double radial_poiseuille_dp(const RadialGeometry& g, double viscosity, double flow) {
  validate(g);
  validate_flow(0.0, viscosity, flow);
  return 6.0 * viscosity * flow * std::log(g.r_out / g.r_in) /
         (std::numbers::pi * g.gap * g.gap * g.gap);
}

double minor_loss_dp(double loss_coefficient, double density, double flow, double area) {
  if (!(loss_coefficient >= 0.0) || !(density > 0.0) || !(area > 0.0) || !std::isfinite(flow))
    throw InputError("minor loss needs K >= 0, density > 0, area > 0 and a finite flow");
  const double velocity = flow / area;
  return 0.5 * loss_coefficient * density * velocity * std::abs(velocity);
}

double reynolds_number(double density, double viscosity, double flow, double area,
                       double hydraulic_diameter) {
  if (!(density > 0.0) || !(viscosity > 0.0) || !(area > 0.0) || !(hydraulic_diameter > 0.0))
    throw InputError("Reynolds number needs density, viscosity, area, hydraulic diameter > 0");
  return density * std::abs(flow) / area * hydraulic_diameter / viscosity;
}

}  // namespace rheomag::fluid
