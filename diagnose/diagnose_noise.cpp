// Robust difference-based estimate of white noise.

#include "diagnose/diagnose_noise.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace rheomag::diagnose {

namespace {

/// Median of v (v is reordered).
double median(std::vector<double>& v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

double noise_sigma(const std::vector<double>& x) {
  if (x.size() < 8) return 0.0;
  std::vector<double> d(x.size() - 3);
  for (std::size_t k = 0; k < d.size(); ++k)
    d[k] = x[k + 3] - 3.0 * x[k + 2] + 3.0 * x[k + 1] - x[k];
  const double center = median(d);
  for (double& v : d) v = std::abs(v - center);
  return 1.4826 * median(d) / std::sqrt(20.0);
}

std::vector<std::size_t> step_intervals(const std::vector<double>& u) {
  if (u.size() < 3) return {};
  std::vector<double> move(u.size() - 1);
  for (std::size_t k = 0; k + 1 < u.size(); ++k) move[k] = std::abs(u[k + 1] - u[k]);
  auto sorted = move;
  const auto [lo, hi] = std::minmax_element(u.begin(), u.end());
  const double step = std::max(0.05 * (*hi - *lo), 10.0 * median(sorted));
  std::vector<std::size_t> out;
  if (!(step > 0.0)) return out;
  for (std::size_t j = 0; j < move.size(); ++j)
    if (move[j] > step) out.push_back(j);
  return out;
}

std::vector<bool> away_from_steps(const std::vector<double>& prediction) {
  const auto steps = step_intervals(prediction);
  if (steps.empty()) return {};
  const std::size_t n = prediction.size();
  std::vector<bool> keep(n, true);
  for (std::size_t j : steps)
    for (std::size_t k = j > 0 ? j - 1 : 0; k <= std::min(j + 2, n - 1); ++k) keep[k] = false;
  return keep;
}

SmoothedDrive savitzky_golay(const std::vector<double>& x, double dt, std::size_t half_width) {
  SmoothedDrive out;
  out.values = x;
  const auto h = static_cast<int>(half_width);
  if (x.size() < 2 * half_width + 1 || h < 2) return out;
  // Weights of the centre value of a least-squares cubic: first row of (A^T A)^-1 A^T.
  Eigen::MatrixXd a(2 * h + 1, 4);
  for (int k = -h; k <= h; ++k)
    for (int p = 0; p < 4; ++p) a(k + h, p) = std::pow(static_cast<double>(k), p);
  const Eigen::VectorXd w = (a.transpose() * a).ldlt().solve(a.transpose()).row(0).transpose();
  for (std::size_t i = half_width; i + half_width < x.size(); ++i) {
    double v = 0.0;
    for (int k = -h; k <= h; ++k) v += w(k + h) * x[i + static_cast<std::size_t>(k)];
    out.values[i] = v;
  }
  // -3 dB point of H(f) = sum_k w_k cos(2 pi f k dt) (symmetric weights), scanned upwards.
  const double nyquist = 0.5 / dt;
  for (int s = 1; s <= 2000; ++s) {
    const double f = nyquist * s / 2000.0;
    double gain = 0.0;
    for (int k = -h; k <= h; ++k) gain += w(k + h) * std::cos(2 * M_PI * f * k * dt);
    if (std::abs(gain) < std::sqrt(0.5)) {
      out.bandwidth = f;
      break;
    }
  }
  return out;
}

}  // namespace rheomag::diagnose
