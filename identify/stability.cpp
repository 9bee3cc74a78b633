// Simulation stability of black-box models: poles of the output recursion, bounded free run.

#include "identify/stability.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rheomag::identify {

namespace {

/// The values of parameters prefix1, prefix2, ... in order (stops at the first missing index).
std::vector<double> numbered_params(const std::vector<NamedValue>& params,
                                    const std::string& prefix) {
  std::vector<double> out;
  for (long i = 1;; ++i) {
    const std::string name = numbered(prefix, i);
    const auto it = std::find_if(params.begin(), params.end(),
                                 [&](const NamedValue& p) { return p.first == name; });
    if (it == params.end()) return out;
    out.push_back(it->second);
  }
}

std::string text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

double largest_root_modulus(const std::vector<double>& c) {
  const auto n = static_cast<Eigen::Index>(c.size());
  if (n == 0) return 0.0;
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index j = 0; j < n; ++j) companion(0, j) = -c[static_cast<std::size_t>(j)];
  for (Eigen::Index i = 1; i < n; ++i) companion(i, i - 1) = 1.0;
  const Eigen::VectorXcd roots = companion.eigenvalues();
  double radius = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) radius = std::max(radius, std::abs(roots(i)));
  return radius;
}

StabilityVerdict check_simulation_stability(const IdentModel& model, const IoData& data,
                                            double peak_limit) {
  StabilityVerdict v;
  const std::string name = model.name();
  const std::string family = name.substr(0, name.find(':'));
  const std::vector<NamedValue> params = model.params();
  std::vector<double> recursion;
  if (family == "arx") recursion = numbered_params(params, "a");
  if (family == "hw") recursion = numbered_params(params, "f");
  if (family == "narx") {  // linear terms y(k-i) of y(k) = sum c_i y(k-i) + ...: z^n - c_1 ...
    const auto na = std::find_if(params.begin(), params.end(),
                                 [](const NamedValue& p) { return p.first == "na"; });
    for (long i = 1; na != params.end() && i <= static_cast<long>(na->second); ++i) {
      const std::string name = numbered("y(k-", i) + ")";
      const auto it = std::find_if(params.begin(), params.end(),
                                   [&](const NamedValue& p) { return p.first == name; });
      recursion.push_back(it == params.end() ? 0.0 : -it->second);
    }
  }
  if (!recursion.empty()) {
    v.pole_radius = largest_root_modulus(recursion);
    if (!(*v.pole_radius < 1.0)) {
      v.stable = false;
      v.reason = "a pole of the output recursion lies at |z| = " + text(*v.pole_radius) +
                 " (outside the unit circle)";
    }
  }
  const Eigen::VectorXd yhat = model.run(data, EvalMode::simulation);
  const double mean = data.y.mean();
  const double measured = (data.y.array() - mean).abs().maxCoeff();
  const auto skip =
      std::min<Eigen::Index>(std::max<std::ptrdiff_t>(model.warmup(), 0), yhat.size());
  double peak = 0.0;
  bool finite = true;
  for (Eigen::Index i = skip; i < yhat.size(); ++i) {
    if (!std::isfinite(yhat(i))) {
      finite = false;
      break;
    }
    peak = std::max(peak, std::abs(yhat(i) - mean));
  }
  v.peak_ratio = measured > 0.0 ? peak / measured : (peak > 0.0 ? INFINITY : 0.0);
  if (!finite || !(v.peak_ratio <= peak_limit)) {
    v.stable = false;
    if (!v.reason.empty()) v.reason += "; ";
    v.reason += finite ? "the free-run output reaches " + text(v.peak_ratio) +
                             " times the measured peak deviation (limit " + text(peak_limit) + ")"
                       : "the free-run output becomes non-finite";
  }
  return v;
}

}  // namespace rheomag::identify
