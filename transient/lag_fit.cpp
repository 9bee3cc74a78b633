#include "transient/lag_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

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

}  // namespace rheomag::transient
