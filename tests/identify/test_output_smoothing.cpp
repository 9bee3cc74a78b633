// The recording-processing smoothing of the damper model (lumped/output_smoothing.hpp): the centred
// moving average against closed forms (a clipped ramp, a sine's sinc gain and its derivative in
// the window), the drive period, and a family fit that recovers a known window from simulated
// recordings and predicts another stroke and frequency.

#include <gtest/gtest.h>

#include <ceres/jet.h>

#include <cmath>
#include <vector>

#include "identify/current_dependent_fit.hpp"
#include "identify/greybox.hpp"
#include "lumped/output_smoothing.hpp"
#include "lumped/phenomenological.hpp"

using namespace rheomag::lumped;
using namespace rheomag::identify;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Samples t_k = t0 + k h, k < n.
std::vector<double> times(double t0, double h, std::size_t n) {
  std::vector<double> t(n);
  for (std::size_t k = 0; k < n; ++k) t[k] = t0 + h * static_cast<double>(k);
  return t;
}

/// Centred moving average over w of sin(2 pi f t): sin(2 pi f t) sin(pi f w) / (pi f w).
double sine_average(double t, double f, double w) {
  return std::sin(2 * kPi * f * t) * std::sin(kPi * f * w) / (kPi * f * w);
}

}  // namespace

// A ramp clipped at +-1 (y = clamp(t / r, -1, 1), knots on the grid) is piecewise linear, so its
// moving average is exact: (G(t + w/2) - G(t - w/2)) / w with G(s) = s^2 / (2 r) for |s| <= r,
// |s| - r / 2 beyond. Tolerance 1e-12 (rounding).
TEST(OutputSmoothing, BoxcarOfAClippedRampIsExact) {
  const double r = 0.01, w = 0.1, h = 1e-3;
  const std::vector<double> t = times(-0.5, h, 1001);
  std::vector<double> y(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) y[k] = std::clamp(t[k] / r, -1.0, 1.0);
  centred_boxcar(t.data(), t.size(), w, y.data());
  const auto G = [&](double s) { return std::abs(s) <= r ? s * s / (2 * r) : std::abs(s) - r / 2; };
  for (std::size_t k = 100; k + 100 < t.size(); ++k)
    EXPECT_NEAR(y[k], (G(t[k] + w / 2) - G(t[k] - w / 2)) / w, 1e-12) << t[k];
  EXPECT_NEAR(y.front(), -1.0, 1e-12);  // window shrunk to nothing at the ends
  EXPECT_NEAR(y.back(), 1.0, 1e-12);
}

// A sine's moving average has the gain sin(pi f w) / (pi f w) (0.9836 for w = T / 10). The
// trapezoidal integral of the sampled sine is second order: halving the sampling step divides the
// largest error by 3.5-4.5 (4 expected), and at 100 samples per period it is below 1e-3.
TEST(OutputSmoothing, BoxcarOfASineHasTheSincGainAtSecondOrder) {
  const double f = 1.0, w = 0.1;
  const auto worst_error = [&](double h) {
    const std::vector<double> t = times(0.0, h, static_cast<std::size_t>(std::lround(4.0 / h)) + 1);
    std::vector<double> y(t.size());
    for (std::size_t k = 0; k < t.size(); ++k) y[k] = std::sin(2 * kPi * f * t[k]);
    centred_boxcar(t.data(), t.size(), w, y.data());
    double worst = 0.0;
    for (std::size_t k = 0; k < t.size(); ++k)
      if (t[k] > w && t[k] < 4.0 - w)
        worst = std::max(worst, std::abs(y[k] - sine_average(t[k], f, w)));
    return worst;
  };
  const double e1 = worst_error(0.01), e2 = worst_error(0.005);
  EXPECT_LT(e1, 1e-3);
  EXPECT_GT(e1 / e2, 3.5);
  EXPECT_LT(e1 / e2, 4.5);
}

// The window width is differentiated by Jets (the fit estimates it): d/dw of the sine's average
// against the derivative of the closed form, within 1e-4 of its scale at 1000 samples per period.
TEST(OutputSmoothing, WidthDerivativeMatchesTheClosedForm) {
  using Jet = ceres::Jet<double, 1>;
  const double f = 1.0, w = 0.1, h = 1e-3;
  const std::vector<double> t = times(0.0, h, 2001);
  std::vector<Jet> y(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) y[k] = Jet(std::sin(2 * kPi * f * t[k]));
  centred_boxcar(t.data(), t.size(), Jet(w, 0), y.data());
  const double x = kPi * f * w;
  const double dgain_dw = kPi * f * (x * std::cos(x) - std::sin(x)) / (x * x);
  for (std::size_t k = 200; k < 1800; k += 37)
    EXPECT_NEAR(y[k].v[0], std::sin(2 * kPi * f * t[k]) * dgain_dw,
                1e-4 * std::abs(dgain_dw) + 1e-6)
        << t[k];
}

// The period of a sine with an offset and a phase (0.984 s, sampled at 1 kHz, 10 cycles) within
// 1e-4 s; a drive with fewer than two full cycles or with cycles of different lengths has none.
TEST(OutputSmoothing, DrivePeriodOfSinesAndNonPeriodicDrives) {
  const double period = 0.984;
  const std::vector<double> t = times(0.0, 1e-3, 9840);
  std::vector<double> v(t.size()), chirp(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    v[k] = 0.003 + 0.05 * std::cos(2 * kPi * t[k] / period + 0.7);
    chirp[k] = std::sin(2 * kPi * (0.2 * t[k] + 0.05 * t[k] * t[k]));
  }
  EXPECT_NEAR(drive_period(t, v), period, 1e-4);
  EXPECT_EQ(drive_period(t, chirp), 0.0);
  const std::vector<double> short_t(t.begin(), t.begin() + 1500),
      short_v(v.begin(), v.begin() + 1500);
  EXPECT_EQ(drive_period(short_t, short_v), 0.0);
}
