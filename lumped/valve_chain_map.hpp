#pragma once
// Static valve map from the fluid chain: the pressure drop of a case's magnetised gaps
// (valve::ValveChain, FE field per current; tabulated by coupling/valve_chain_tabulation.hpp) on
// a current x flow grid, split into
// the yield part and the viscous (Poiseuille) part so each carries its own calibration scale, and
// its inverse Q(dp, I) for rigs with compliant chambers. Templates so Ceres Jets flow through the
// scales and the states.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "lumped/smooth.hpp"

namespace rheomag::lumped {

/// dp(I, Q) of a case's valve on a grid: dp = yield(I, |Q|) sgn Q + viscous_resistance Q.
struct ChainMapTable {
  std::string case_file;            ///< the FE case it came from
  std::vector<double> current;      ///< [A] increasing, current[0] = 0
  std::vector<double> flow;         ///< [m^3/s] increasing, flow[0] > 0 (small)
  std::vector<double> yield;        ///< [Pa] dp_yield at (current[i], flow[k]), i * nf + k
  double viscous_resistance = 0.0;  ///< [Pa s/m^3] Newtonian dp / Q of the gaps in series
  /// Yield part [Pa] at grid flow k, current interpolated linearly (clamped to the grid).
  template <class T>
  T yield_at(std::size_t k, const T& i) const;
};

/// Pressure drop [Pa] at flow Q [m^3/s] and field current i [A]:
/// yield_scale * yield(i, |Q|) tanh(Q / eps_flow) + viscous_scale * R * Q.
template <class T, class S>
T chain_pressure_drop(const ChainMapTable& m, const T& flow, const T& current, const S& yield_scale,
                      const S& viscous_scale, double eps_flow);

/// Flow [m^3/s] at pressure drop dp [Pa]: the inverse of chain_pressure_drop with the plug switch
/// regularised (ramp width viscous_scale * R * eps_flow), odd in dp.
template <class T, class S>
T chain_flow(const ChainMapTable& m, const T& dp, const T& current, const S& yield_scale,
             const S& viscous_scale, double eps_flow);

// ---- implementation -------------------------------------------------------------------------

namespace chain_detail {
/// Index k of the grid segment [x[k], x[k+1]] holding v (clamped to the end segments).
inline std::size_t segment(const std::vector<double>& x, double v) {
  auto it = std::upper_bound(x.begin(), x.end(), v);
  if (it == x.begin()) return 0;
  return std::min<std::size_t>(static_cast<std::size_t>(it - x.begin()) - 1, x.size() - 2);
}
}  // namespace chain_detail

template <class T>
T ChainMapTable::yield_at(std::size_t k, const T& i) const {
  const std::size_t nf = flow.size();
  if (current.size() == 1) return T(yield[k]);
  const double iv = std::clamp(std::abs(value_of(i)), current.front(), current.back());
  const std::size_t j = chain_detail::segment(current, iv);
  const double y0 = yield[j * nf + k], y1 = yield[(j + 1) * nf + k];
  const double slope = (y1 - y0) / (current[j + 1] - current[j]);
  if (std::abs(value_of(i)) > current.back() || std::abs(value_of(i)) < current.front())
    return T(y0 + slope * (iv - current[j]));  // clamped: flat beyond the grid
  using std::abs;
  return y0 + slope * (abs(i) - current[j]);
}

template <class T, class S>
T chain_pressure_drop(const ChainMapTable& m, const T& flow, const T& current, const S& yield_scale,
                      const S& viscous_scale, double eps_flow) {
  const T q = smooth_abs(flow, eps_flow);
  const double qv = value_of(q);
  T y;
  if (qv <= m.flow.front()) {
    y = m.yield_at(0, current);
  } else {
    const std::size_t k = chain_detail::segment(m.flow, qv);
    const T y0 = m.yield_at(k, current), y1 = m.yield_at(k + 1, current);
    y = y0 + (y1 - y0) * ((q - m.flow[k]) / (m.flow[k + 1] - m.flow[k]));
  }
  return yield_scale * y * smooth_sign(flow, eps_flow) +
         viscous_scale * m.viscous_resistance * flow;
}

template <class T, class S>
T chain_flow(const ChainMapTable& m, const T& dp, const T& current, const S& yield_scale,
             const S& viscous_scale, double eps_flow) {
  // f(q) - f(0) on the knots q = 0, flow[0], ..., with f(q) = s_y yield(q) + s_v R q (increasing).
  const T plug = yield_scale * m.yield_at(0, current);
  const S resistance = viscous_scale * m.viscous_resistance;
  const double width = value_of(resistance) * eps_flow;
  auto invert = [&](const T& excess) -> T {  // q >= 0 with f(q) - f(0) = excess >= 0
    T q_lo = T(0.0), e_lo = T(0.0);
    T q_hi = T(m.flow.front()), e_hi = resistance * m.flow.front();
    std::size_t k = 0;
    while (value_of(e_hi) < value_of(excess) && k + 1 < m.flow.size()) {
      q_lo = q_hi;
      e_lo = e_hi;
      ++k;
      q_hi = T(m.flow[k]);
      e_hi = yield_scale * m.yield_at(k, current) + resistance * m.flow[k] - plug;
    }
    return q_lo + (q_hi - q_lo) * ((excess - e_lo) / (e_hi - e_lo));  // linear beyond the grid
  };
  return invert(smooth_ramp(dp - plug, width)) - invert(smooth_ramp(-dp - plug, width));
}

}  // namespace rheomag::lumped
