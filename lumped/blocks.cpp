// Algebraic laws of the lumped blocks.

#include "lumped/blocks.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "lumped/slit_law.hpp"
#include "lumped/smooth.hpp"

namespace rheomag::lumped {

namespace {

/// Piecewise-linear interpolation on increasing x, linear extrapolation at the right end.
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double v) {
  if (x.size() == 1) return y[0];
  auto it = std::upper_bound(x.begin(), x.end(), v);
  std::size_t k = it == x.begin() ? 0 : std::min<std::size_t>(it - x.begin() - 1, x.size() - 2);
  return y[k] + (y[k + 1] - y[k]) * (v - x[k]) / (x[k + 1] - x[k]);
}

}  // namespace

double CoilBlock::flux_of_current(double i) const {
  const double s = i < 0 ? -1.0 : 1.0;
  return s * interpolate(table_current, table_flux, std::abs(i));
}

double CoilBlock::current_of_flux(double lambda) const {
  const double s = lambda < 0 ? -1.0 : 1.0;
  return s * interpolate(table_flux, table_current, std::abs(lambda));
}

double DuhemBlock::incremental_inductance(double i, double lambda, double direction) const {
  const double f = b1 * std::tanh(b2 * i);
  // Kept >= 0.05 d so di/dt stays finite (the Duhem operator needs a positive slope).
  return std::max(d + a * direction * (f - lambda), 0.05 * d);
}

double eddy_time_constant(double relative_permeability, double conductivity, double radius) {
  constexpr double mu0 = 4e-7 * 3.14159265358979323846, j01 = 2.404825557695773;
  if (!(relative_permeability > 0 && conductivity > 0 && radius > 0))
    throw InputError("eddy_time_constant: permeability, conductivity and radius must be > 0");
  return mu0 * relative_permeability * conductivity * radius * radius / (j01 * j01);
}

double DriverBlock::saturate(double v) const {
  return voltage_limit * std::tanh(v / voltage_limit);
}

double ValveMapBlock::yield(double current) const {
  if (yield_current.empty()) return 0.0;
  const double i = std::clamp(std::abs(current), yield_current.front(), yield_current.back());
  return yield_scale * interpolate(yield_current, yield_pressure, i);
}

double ValveMapBlock::pressure_drop(double flow, double current, double viscous_factor) const {
  if (chain)
    return chain_pressure_drop(*chain, flow, current, yield_scale, viscous_scale * viscous_factor,
                               regularisation_flow);
  const double resistance = viscous_factor * viscous_resistance;
  double py = yield(current);
  if (slit_fraction > 0.0 && py > 0.0) {
    const double delta = slit_plug_at_flow(resistance * std::abs(flow) / py);
    py *= 1.0 - slit_fraction * delta * delta / 3.0;
  }
  return py * smooth_sign(flow, regularisation_flow) + resistance * flow;
}

double ValveMapBlock::flow(double dp, double current, double viscous_factor) const {
  if (chain)
    return chain_flow(*chain, dp, current, yield_scale, viscous_scale * viscous_factor,
                      regularisation_flow);
  const double resistance = viscous_factor * viscous_resistance;
  const double py = yield(current), width = resistance * regularisation_flow;
  if (!(slit_fraction > 0.0 && py > 0.0))
    return (smooth_ramp(dp - py, width) - smooth_ramp(-dp - py, width)) / resistance;
  // The knee: the excess over the onset p_y (1 - k/3), regularised by the same smooth ramp as
  // the line (k = 0 gives the line's ramp / R), drives the slit law's flow. The composition is
  // smooth and increasing; below the onset its creep is the ramp's tail through the knee.
  const double onset = py * (1.0 - slit_fraction / 3.0);
  return knee_flow(smooth_ramp(dp - onset, width), py, resistance, slit_fraction) -
         knee_flow(smooth_ramp(-dp - onset, width), py, resistance, slit_fraction);
}

double ChamberBlock::capacitance(double pressure) const {
  double c = oil_volume / bulk_modulus;
  if (air_volume > 0.0) {
    const double ratio = precharge / pressure;
    const double v_air =
        air_volume * (polytropic == 1.0 ? ratio : std::pow(ratio, 1.0 / polytropic));
    c += v_air / (polytropic * pressure);
  }
  return c;
}

double ChamberBlock::stored_volume(double pressure) const {
  double v = oil_volume / bulk_modulus * (pressure - precharge);
  if (air_volume > 0.0) {
    const double ratio = precharge / pressure;
    v += air_volume * (1.0 - (polytropic == 1.0 ? ratio : std::pow(ratio, 1.0 / polytropic)));
  }
  return v;
}

double ChamberBlock::pressure_at(double volume) const {
  const double c = oil_volume / bulk_modulus, a = air_volume, p0 = precharge;
  if (!(a > 0.0)) return p0 + volume / c;
  // Isothermal: c p^2 + b p - a p0 = 0 with b = a - c p0 - volume; its positive root, written
  // without cancellation.
  const double b = a - c * p0 - volume, disc = std::sqrt(b * b + 4.0 * c * a * p0);
  double p = b >= 0.0 ? 2.0 * a * p0 / (b + disc) : (disc - b) / (2.0 * c);
  if (polytropic == 1.0) return p;
  // Polytropic: Newton on u = ln p (stored_volume is increasing in u), from the isothermal root.
  double u = std::log(p);
  for (int it = 0; it < 60; ++it) {
    const double e = std::exp(u), air = std::pow(p0 / e, 1.0 / polytropic);
    const double g = c * (e - p0) + a * (1.0 - air) - volume;
    const double dg = c * e + a * air / polytropic;
    const double du = g / dg;
    u -= du;
    if (std::abs(du) < 1e-14) break;
  }
  return std::exp(u);
}

}  // namespace rheomag::lumped
