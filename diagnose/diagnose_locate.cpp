// Windowed residual energy with regime tags, and residual statistics.

#include "diagnose/diagnose_locate.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rheomag::diagnose {

namespace {

double mean_of(const std::vector<double>& v, std::size_t b, std::size_t e) {
  double s = 0.0;
  for (std::size_t k = b; k < e; ++k) s += v[k];
  return e > b ? s / static_cast<double>(e - b) : 0.0;
}

double rms_of(const std::vector<double>& v, std::size_t b, std::size_t e) {
  double s = 0.0;
  for (std::size_t k = b; k < e; ++k) s += v[k] * v[k];
  return e > b ? std::sqrt(s / static_cast<double>(e - b)) : 0.0;
}

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

/// The coil input column of a recording (current preferred), or nullptr.
const std::vector<double>* coil_input(const lumped::Recording& rec) {
  for (const char* name : {"current", "current_cmd", "voltage", "command"}) {
    auto it = rec.columns.find(name);
    if (it != rec.columns.end()) return &it->second;
  }
  return nullptr;
}

/// True if the velocity changes sign (beyond 1 % of its peak) within [b, e).
bool flow_reverses(const lumped::Recording& rec, std::size_t b, std::size_t e) {
  auto vel = rec.columns.find("velocity");
  if (vel == rec.columns.end() || e <= b) return false;
  const double vmax = max_abs(vel->second);
  double lo = 0.0, hi = 0.0;
  for (std::size_t k = b; k < e; ++k) {
    lo = std::min(lo, vel->second[k]);
    hi = std::max(hi, vel->second[k]);
  }
  return vmax > 0 && lo < -0.01 * vmax && hi > 0.01 * vmax;
}

/// "current rising edge", "current falling edge" or "" for the coil input over [b, e).
std::string current_edge(const std::vector<double>* c, std::size_t b, std::size_t e) {
  if (!c || e <= b + 1) return "";
  const double range =
      *std::max_element(c->begin(), c->end()) - *std::min_element(c->begin(), c->end());
  double rise = 0.0, fall = 0.0;
  for (std::size_t k = b + 1; k < e; ++k) {
    const double d = (*c)[k] - (*c)[k - 1];
    (d > 0 ? rise : fall) += std::abs(d);
  }
  if (range > 0 && rise > 0.2 * range && rise > 2 * fall) return "current rising edge";
  if (range > 0 && fall > 0.2 * range && fall > 2 * rise) return "current falling edge";
  return "";
}

/// Regime of window [b, e): what the drive does in it, or in the window before it (a lagging
/// response shows after its cause), else what the residual looks like.
std::string regime_of(const lumped::Recording& rec, const std::vector<double>& r, std::size_t b,
                      std::size_t e) {
  const auto* c = coil_input(rec);
  if (flow_reverses(rec, b, e)) return "flow reversal";
  if (auto edge = current_edge(c, b, e); !edge.empty()) return edge;
  const std::size_t before = b >= e - b ? b - (e - b) : 0;
  if (flow_reverses(rec, before, b)) return "flow reversal";
  if (auto edge = current_edge(c, before, b); !edge.empty()) return edge;
  double cmax = 0.0, cmin = 0.0;
  if (c) {
    cmax = *std::max_element(c->begin(), c->end());
    cmin = *std::min_element(c->begin(), c->end());
  }
  const double mr = mean_of(r, b, e), rr = rms_of(r, b, e);
  if (rr > 0 && std::abs(mr) > 0.7 * rr) return "slow drift";
  std::size_t crossings = 0;
  for (std::size_t k = b + 1; k < e; ++k)
    if ((r[k] - mr) * (r[k - 1] - mr) < 0) ++crossings;
  if (e - b > 2 && static_cast<double>(crossings) / static_cast<double>(e - b - 1) > 0.3)
    return "high frequency";
  if (c && mean_of(*c, b, e) > cmin + 0.5 * (cmax - cmin)) return "steady on";
  return "steady off";
}

std::vector<double> derivative(const std::vector<double>& t, const std::vector<double>& v) {
  std::vector<double> d(v.size(), 0.0);
  for (std::size_t k = 0; k < v.size(); ++k) {
    const std::size_t a = k == 0 ? 0 : k - 1, b = std::min(k + 1, v.size() - 1);
    d[k] = (v[b] - v[a]) / (t[b] - t[a]);
  }
  return d;
}

std::vector<double> integral(const std::vector<double>& t, const std::vector<double>& v) {
  std::vector<double> s(v.size(), 0.0);
  for (std::size_t k = 1; k < v.size(); ++k)
    s[k] = s[k - 1] + 0.5 * (v[k] + v[k - 1]) * (t[k] - t[k - 1]);
  return s;
}

std::vector<double> demeaned(std::vector<double> v) {
  const double m = mean_of(v, 0, v.size());
  for (double& x : v) x -= m;
  return v;
}

/// Normalised correlation of a and b shifted by `lag` samples (b leads for lag > 0).
double correlation_at(const std::vector<double>& a, const std::vector<double>& b, long lag) {
  const long n = static_cast<long>(a.size());
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (long k = std::max(0L, lag); k < std::min(n, n + lag); ++k) {
    sab += a[k] * b[k - lag];
    saa += a[k] * a[k];
    sbb += b[k - lag] * b[k - lag];
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

/// Best lag (samples, within +-max_lag) and the correlation there.
std::pair<long, double> best_lag(const std::vector<double>& a, const std::vector<double>& b,
                                 long max_lag) {
  std::pair<long, double> best{0, 0.0};
  for (long lag = -max_lag; lag <= max_lag; ++lag) {
    const double c = correlation_at(a, b, lag);
    if (std::abs(c) > std::abs(best.second)) best = {lag, c};
  }
  return best;
}

}  // namespace

std::vector<MismatchWindow> locate_mismatch(const lumped::Recording& rec,
                                            const std::vector<double>& residual, int windows,
                                            double cover, std::size_t max_windows) {
  const std::size_t n = residual.size();
  const std::size_t w = std::max<std::size_t>(n / static_cast<std::size_t>(windows), 2);
  double total = 0.0;
  for (double r : residual) total += r * r;
  std::vector<MismatchWindow> all;
  for (std::size_t b = 0; b + w / 2 < n; b += w) {
    const std::size_t e = std::min(n, b + w);
    MismatchWindow win;
    win.begin = b;
    win.end = e;
    win.t_start = rec.t[b];
    win.t_end = rec.t[e - 1];
    double s = 0.0;
    for (std::size_t k = b; k < e; ++k) s += residual[k] * residual[k];
    win.share = total > 0 ? s / total : 0.0;
    win.regime = regime_of(rec, residual, b, e);
    all.push_back(win);
  }
  std::sort(all.begin(), all.end(),
            [](const MismatchWindow& a, const MismatchWindow& b) { return a.share > b.share; });
  std::vector<MismatchWindow> out;
  double covered = 0.0;
  for (const auto& win : all) {
    if (covered >= cover || out.size() >= max_windows) break;
    out.push_back(win);
    covered += win.share;
  }
  return out;
}

ResidualStats residual_statistics(const lumped::Recording& rec,
                                  const std::vector<std::string>& drive,
                                  const std::vector<double>& measured,
                                  const std::vector<double>& prediction) {
  ResidualStats st;
  const std::size_t n = measured.size();
  std::vector<double> r(n);
  for (std::size_t k = 0; k < n; ++k) r[k] = measured[k] - prediction[k];
  r = demeaned(r);
  const double dt = (rec.t.back() - rec.t.front()) / static_cast<double>(n - 1);
  // Whiteness: Ljung-Box over 20 lags.
  double r0 = 0.0;
  for (double x : r) r0 += x * x;
  const int h = 20;
  for (int lag = 1; lag <= h && lag < static_cast<int>(n); ++lag) {
    double c = 0.0;
    for (std::size_t k = lag; k < n; ++k) c += r[k] * r[k - lag];
    const double rho = r0 > 0 ? c / r0 : 0.0;
    if (lag == 1) st.lag1_autocorrelation = rho;
    st.ljung_box_q += rho * rho / static_cast<double>(n - lag);
  }
  st.ljung_box_q *= static_cast<double>(n) * static_cast<double>(n + 2);
  st.white = st.ljung_box_q < 37.57;
  // Cross-correlation with inputs, their derivatives and integrals.
  const long max_lag = std::min<long>(static_cast<long>(n / 20), 200);
  for (const auto& name : drive) {
    auto it = rec.columns.find(name);
    if (it == rec.columns.end()) continue;
    const auto& u = it->second;
    const std::pair<std::string, std::vector<double>> signals[] = {
        {name, demeaned(u)},
        {"d/dt " + name, demeaned(derivative(rec.t, u))},
        {"integral " + name, demeaned(integral(rec.t, u))}};
    for (const auto& [label, s] : signals) {
      const auto [lag, c] = best_lag(r, s, max_lag);
      st.correlations.push_back({label, c, static_cast<double>(lag) * dt});
    }
    // Loop in the (u, r) plane.
    const auto du = derivative(rec.t, u);
    std::vector<std::size_t> moving;
    for (std::size_t k = 0; k < n; ++k)
      if (du[k] != 0.0) moving.push_back(k);
    if (moving.size() >= 6 && r0 > 0) {
      std::sort(moving.begin(), moving.end(),
                [&](std::size_t a, std::size_t b) { return std::abs(du[a]) < std::abs(du[b]); });
      const double rr = std::sqrt(r0 / static_cast<double>(n));
      auto opening = [&](std::size_t from, std::size_t to) {
        double s = 0.0;
        for (std::size_t i = from; i < to; ++i) s += r[moving[i]] * (du[moving[i]] > 0 ? 1 : -1);
        return std::abs(s / static_cast<double>(to - from)) / rr;
      };
      const std::size_t third = moving.size() / 3;
      ResidualLoop loop;
      loop.input = name;
      loop.opening = opening(0, moving.size());
      const double fast = opening(moving.size() - third, moving.size());
      loop.slow_fast_ratio = fast > 0 ? opening(0, third) / fast : 0.0;
      loop.rate_independent = loop.opening > 0.2 && loop.slow_fast_ratio > 0.5;
      double memory = 0.0, direction = 0.0;
      std::size_t remembered = 0;
      for (std::size_t k = 0; k < n; ++k) {
        if (du[k] != 0.0) direction = du[k] > 0 ? 1.0 : -1.0;
        if (direction == 0.0) continue;
        memory += r[k] * direction;
        ++remembered;
      }
      if (remembered > 0)
        loop.memory_opening = std::abs(memory / static_cast<double>(remembered)) / rr;
      st.loops.push_back(loop);
    }
  }
  std::sort(st.correlations.begin(), st.correlations.end(),
            [](const auto& a, const auto& b) { return std::abs(a.value) > std::abs(b.value); });
  // Lag of the measurement behind the model.
  const auto [lag, c] = best_lag(demeaned(measured), demeaned(prediction), max_lag);
  (void)c;
  st.output_lag = static_cast<double>(lag) * dt;
  return st;
}

}  // namespace rheomag::diagnose
