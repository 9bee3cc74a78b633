#include "transient/lag_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>
#include <utility>

#include "core/error.hpp"

namespace rheomag::transient {
namespace {

/// Residuals of the normalised response u = (y - end) / (start - end) = sum w_k exp(-t/tau_k)
/// with w = (w_1 .. w_{K-1}, 1 - sum) from linear least squares, as a function of log tau.
struct Projection {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };

  const Eigen::VectorXd& t;
  const Eigen::VectorXd& u;
  int count = 1;
  int inputs() const { return count; }
  int values() const { return static_cast<int>(t.size()); }

  /// Weights for the time constants exp(log_tau).
  Eigen::VectorXd weights(const Eigen::VectorXd& log_tau) const {
    const int k = static_cast<int>(log_tau.size());
    Eigen::MatrixXd e(t.size(), k);
    for (int j = 0; j < k; ++j) e.col(j) = (-t.array() / std::exp(log_tau[j])).exp();
    // u = e_K + sum_{j<K} w_j (e_j - e_K): least squares in w_1..w_{K-1}.
    Eigen::VectorXd w(k);
    if (k == 1) {
      w[0] = 1.0;
      return w;
    }
    Eigen::MatrixXd a(t.size(), k - 1);
    for (int j = 0; j + 1 < k; ++j) a.col(j) = e.col(j) - e.col(k - 1);
    const Eigen::VectorXd head = a.colPivHouseholderQr().solve(u - e.col(k - 1));
    w.head(k - 1) = head;
    w[k - 1] = 1.0 - head.sum();
    return w;
  }
  int operator()(const Eigen::VectorXd& log_tau, Eigen::VectorXd& r) const {
    const Eigen::VectorXd w = weights(log_tau);
    r = -u;
    for (int j = 0; j < log_tau.size(); ++j)
      r += w[j] * (-t.array() / std::exp(log_tau[j])).exp().matrix();
    return 0;
  }
};

}  // namespace

std::vector<Lag> fit_lags(const std::vector<double>& time, const std::vector<double>& values,
                          double start, double end, int count) {
  if (count < 1 || count > 3)
    throw InputError("fit_lags: 1 to 3 lags, got " + std::to_string(count));
  if (time.size() != values.size() || static_cast<int>(time.size()) < 2 * count + 1)
    throw InputError("fit_lags: too few samples for " + std::to_string(count) + " lags");
  if (end == start) throw InputError("fit_lags: the response does not change");
  const int n = static_cast<int>(time.size());
  Eigen::VectorXd t(n), u(n);
  for (int i = 0; i < n; ++i) {
    t[i] = time[i];
    u[i] = (values[i] - end) / (start - end);
  }
  // Start: time constants spread over the response's duration around its 63 % time.
  double t63 = t[n - 1];
  for (int i = 0; i < n; ++i)
    if (u[i] <= std::exp(-1.0)) {
      t63 = std::max(t[i], 1e-12);
      break;
    }
  Eigen::VectorXd log_tau(count);
  for (int j = 0; j < count; ++j) log_tau[j] = std::log(t63) + 1.5 * (j - 0.5 * (count - 1));
  Projection projection{t, u, count};
  Eigen::NumericalDiff<Projection> numeric(projection);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Projection>> lm(numeric);
  lm.parameters.xtol = 1e-12;
  lm.parameters.ftol = 1e-14;
  lm.parameters.maxfev = 2000;
  lm.minimize(log_tau);
  const Eigen::VectorXd w = projection.weights(log_tau);
  std::vector<Lag> lags;
  for (int j = 0; j < count; ++j) lags.push_back({w[j], std::exp(log_tau[j])});
  std::sort(lags.begin(), lags.end(),
            [](const Lag& a, const Lag& b) { return a.time_constant < b.time_constant; });
  return lags;
}

double lag_response(const std::vector<Lag>& lags, double start, double end, double t) {
  double u = 0.0;
  for (const Lag& lag : lags) u += lag.weight * std::exp(-t / lag.time_constant);
  return end + (start - end) * u;
}

namespace {

/// Normalised response of one lag after a dead time: 1 before `delay`, e^(-(t - delay)/tau) after.
double delayed_lag(double t, double delay, double tau) {
  return t <= delay ? 1.0 : std::exp(-(t - delay) / tau);
}

/// Squared error of the delayed lag against the normalised samples u.
double delayed_lag_error(const Eigen::VectorXd& t, const Eigen::VectorXd& u, double delay,
                         double tau) {
  double sum = 0.0;
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    const double e = delayed_lag(t[i], delay, tau) - u[i];
    sum += e * e;
  }
  return sum;
}

/// Minimum of f on [a, b] by golden-section search (f unimodal enough on the bracket).
template <class F>
double golden_minimum(F f, double a, double b, int iterations) {
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - r * (b - a), d = a + r * (b - a), fc = f(c), fd = f(d);
  for (int k = 0; k < iterations; ++k) {
    if (fc < fd) {
      b = d, d = c, fd = fc;
      c = b - r * (b - a), fc = f(c);
    } else {
      a = c, c = d, fc = fd;
      d = a + r * (b - a), fd = f(d);
    }
  }
  return fc < fd ? c : d;
}

/// Minimum of f on [a, b] that need not be unimodal: the best of 48 equally spaced points, then
/// golden section between its neighbours.
template <class F>
double scanned_minimum(F f, double a, double b) {
  constexpr int kPoints = 48;
  const double h = (b - a) / (kPoints - 1);
  int best = 0;
  double best_value = f(a);
  for (int k = 1; k < kPoints; ++k)
    if (const double v = f(a + k * h); v < best_value) best = k, best_value = v;
  return golden_minimum(f, a + std::max(best - 1, 0) * h, a + std::min(best + 1, kPoints - 1) * h,
                        50);
}

/// The best log time constant for a given delay, and its squared error.
std::pair<double, double> best_tau(const Eigen::VectorXd& t, const Eigen::VectorXd& u, double delay,
                                   double log_lo, double log_hi) {
  const auto error = [&](double log_tau) {
    return delayed_lag_error(t, u, delay, std::exp(log_tau));
  };
  const double log_tau = scanned_minimum(error, log_lo, log_hi);
  return {log_tau, error(log_tau)};
}

/// One lag after a dead time fitted to the normalised samples: the delay on a grid of the
/// sample times before the 63 % time, refined by golden section between its grid neighbours;
/// the log time constant by golden section for each delay.
std::pair<double, double> fit_delayed_lag(const Eigen::VectorXd& t, const Eigen::VectorXd& u) {
  const Eigen::Index n = t.size();
  const double span = std::max(t[n - 1], 1e-12);
  const double log_lo = std::log(span * 1e-6), log_hi = std::log(span * 1e3);
  std::vector<double> grid{0.0};
  for (Eigen::Index i = 0; i < n && u[i] > std::exp(-1.0); ++i)
    if (t[i] > grid.back()) grid.push_back(t[i]);
  std::size_t best = 0;
  double best_error = best_tau(t, u, grid[0], log_lo, log_hi).second;
  for (std::size_t k = 1; k < grid.size(); ++k) {
    const double e = best_tau(t, u, grid[k], log_lo, log_hi).second;
    if (e < best_error) best = k, best_error = e;
  }
  const double lo = grid[best > 0 ? best - 1 : 0], hi = grid[std::min(best + 1, grid.size() - 1)];
  double delay = grid[best];
  if (hi > lo) {
    const double refined = golden_minimum(
        [&](double d) { return best_tau(t, u, d, log_lo, log_hi).second; }, lo, hi, 40);
    if (best_tau(t, u, refined, log_lo, log_hi).second < best_error) delay = refined;
  }
  return {delay, std::exp(best_tau(t, u, delay, log_lo, log_hi).first)};
}

/// Normalised response of a double lag: (1 + shape t/tau) e^(-t/tau).
double double_lag(double t, double tau, double shape) {
  return (1.0 + shape * t / tau) * std::exp(-t / tau);
}

/// The shape of a double lag of time constant tau fitted to the normalised samples (linear least
/// squares: u - e = shape (t/tau) e with e = e^(-t/tau)), and its squared error.
std::pair<double, double> double_lag_shape(const Eigen::VectorXd& t, const Eigen::VectorXd& u,
                                           double tau) {
  double num = 0.0, den = 0.0;
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    const double e = std::exp(-t[i] / tau), g = t[i] / tau * e;
    num += g * (u[i] - e);
    den += g * g;
  }
  const double shape = den > 0.0 ? num / den : 0.0;
  double sum = 0.0;
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    const double r = double_lag(t[i], tau, shape) - u[i];
    sum += r * r;
  }
  return {shape, sum};
}

/// A double lag fitted to the normalised samples: (tau, shape).
std::pair<double, double> fit_double_lag(const Eigen::VectorXd& t, const Eigen::VectorXd& u) {
  const double span = std::max(t[t.size() - 1], 1e-12);
  const double log_tau =
      scanned_minimum([&](double l) { return double_lag_shape(t, u, std::exp(l)).second; },
                      std::log(span * 1e-6), std::log(span * 1e3));
  return {std::exp(log_tau), double_lag_shape(t, u, std::exp(log_tau)).first};
}

bool well_conditioned(const std::vector<Lag>& lags) {
  if (lags.size() != 2) return false;
  for (const Lag& lag : lags)
    if (!std::isfinite(lag.weight) || std::abs(lag.weight) > kMaxLagWeight) return false;
  return lags[1].time_constant >= kMinLagSeparation * lags[0].time_constant;
}

}  // namespace

namespace {

/// Largest |model - sample| over the samples relative to |end - start|.
double largest_error(const ReducedModel& model, const std::vector<double>& time,
                     const std::vector<double>& values, double start, double end) {
  double worst = 0.0;
  for (std::size_t i = 0; i < time.size(); ++i)
    worst = std::max(worst, std::abs(reduced_response(model, start, end, time[i]) - values[i]) /
                                std::abs(end - start));
  return worst;
}

}  // namespace

ReducedModel fit_reduced_model(const std::vector<double>& time, const std::vector<double>& values,
                               double start, double end) {
  ReducedModel model;
  model.two_lag_fit = fit_lags(time, values, start, end, 2);
  if (well_conditioned(model.two_lag_fit)) {
    model.form = ReducedForm::two_lags;
    model.lags = model.two_lag_fit;
  } else {
    const Eigen::Index n = static_cast<Eigen::Index>(time.size());
    Eigen::VectorXd t(n), u(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      t[i] = time[static_cast<std::size_t>(i)];
      u[i] = (values[static_cast<std::size_t>(i)] - end) / (start - end);
    }
    const auto [delay, tau] = fit_delayed_lag(t, u);
    model.form = ReducedForm::lag_with_delay;
    model.lags = {{1.0, tau}};
    model.delay = delay;
    ReducedModel double_model = model;
    const auto [double_tau, shape] = fit_double_lag(t, u);
    double_model.form = ReducedForm::double_lag;
    double_model.lags = {{1.0, double_tau}};
    double_model.shape = shape;
    double_model.delay = 0.0;
    if (largest_error(double_model, time, values, start, end) <
        largest_error(model, time, values, start, end))
      model = double_model;
  }
  model.max_error = largest_error(model, time, values, start, end);
  return model;
}

double reduced_response(const ReducedModel& model, double start, double end, double t) {
  switch (model.form) {
    case ReducedForm::two_lags:
      return lag_response(model.lags, start, end, t);
    case ReducedForm::lag_with_delay:
      return end + (start - end) * delayed_lag(t, model.delay, model.lags.front().time_constant);
    case ReducedForm::double_lag:
      return end + (start - end) * double_lag(t, model.lags.front().time_constant, model.shape);
  }
  return end;
}

}  // namespace rheomag::transient
