#pragma once
// The processing a recording applied to its output, which a model's output must go through before
// the two are compared: a centred moving average (boxcar) over a window that is a fixed fraction
// of the drive's period (the UTFSM damper tests were filtered with a moving average over a tenth
// of the period, docs/damper-model.md) and the drive period it is measured against, and the
// removal of the output's mean (those tests' forces had their means removed), or a tare to the
// level the recording shows at rest before its motion starts. Templated so Ceres Jets flow
// through.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "lumped/smooth.hpp"

namespace rheomag::lumped {

/// Times [s] at which v(t) crosses its mean upwards, each counted once the signal has been a tenth
/// of its rms below the mean and then as far above it (noise does not add crossings).
std::vector<double> upward_crossings(const std::vector<double>& t, const std::vector<double>& v);

/// Period [s] of a periodic drive signal v(t) from its upward zero crossings (upward_crossings);
/// 0 if it has fewer than two full cycles or if its cycles differ by more than 20 % (not periodic:
/// no period-relative smoothing applies).
double drive_period(const std::vector<double>& t, const std::vector<double>& v);

/// Replaces y[0..n) on the times t[0..n) by its centred moving average over `width` [s]: the
/// exact mean of the piecewise linear interpolant over [t_i - w/2, t_i + w/2], the window shrunk
/// symmetrically at the ends. Nothing changes for a width <= 0.
template <class T>
void centred_boxcar(const double* t, std::size_t n, const T& width, T* y) {
  if (n < 2 || !(value_of(width) > 0.0)) return;
  std::vector<T> integral(n);  // trapezoidal integral of y from t[0]
  integral[0] = T(0.0);
  for (std::size_t k = 1; k < n; ++k)
    integral[k] = integral[k - 1] + 0.5 * (y[k] + y[k - 1]) * (t[k] - t[k - 1]);
  // Exact integral of the interpolant from t[0] to tau (t[0] <= tau <= t[n-1]).
  const auto integral_to = [&](const T& tau) {
    const double tv = value_of(tau);
    std::size_t j = static_cast<std::size_t>(std::upper_bound(t, t + n, tv) - t);
    j = std::clamp<std::size_t>(j, 1, n - 1) - 1;
    const T s = tau - t[j];
    return integral[j] + s * (y[j] + 0.5 * (y[j + 1] - y[j]) * s / (t[j + 1] - t[j]));
  };
  std::vector<T> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    T half = 0.5 * width;
    const double room = std::min(t[i] - t[0], t[n - 1] - t[i]);
    if (value_of(half) > room) half = T(room);
    out[i] = value_of(half) > 0.0
                 ? (integral_to(t[i] + half) - integral_to(t[i] - half)) / (2.0 * half)
                 : y[i];
  }
  std::copy(out.begin(), out.end(), y);
}

/// True if the mean of `y` is zero to within 1e-4 of its rms: an output whose mean the recording's
/// processing removed (a measured signal's mean is that small only by construction).
inline bool output_mean_removed(const std::vector<double>& y) {
  if (y.empty()) return false;
  double sum = 0.0, squares = 0.0;
  for (double v : y) {
    sum += v;
    squares += v * v;
  }
  const double n = static_cast<double>(y.size());
  return squares > 0.0 && std::abs(sum / n) <= 1e-4 * std::sqrt(squares / n);
}

/// Subtracts the mean of y[0..n) from each of them.
template <class T>
void remove_mean(T* y, std::size_t n) {
  if (n == 0) return;
  T sum = T(0.0);
  for (std::size_t i = 0; i < n; ++i) sum += y[i];
  const T mean = sum / static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) y[i] -= mean;
}

/// Shifts y[0..n) so that its mean over the first `rest` samples is `level` (a tare; rest <= n).
template <class T>
void tare(T* y, std::size_t n, std::size_t rest, T level) {
  if (rest == 0 || rest > n) return;
  T sum = T(0.0);
  for (std::size_t i = 0; i < rest; ++i) sum += y[i];
  const T shift = level - sum / static_cast<double>(rest);
  for (std::size_t i = 0; i < n; ++i) y[i] += shift;
}

}  // namespace rheomag::lumped
