// The noise floor estimate of the diagnosis (diagnose/diagnose_noise.hpp). Reference: for white
// Gaussian noise of std sigma the third difference has variance 20 sigma^2 (binomial
// coefficients 1, 3, 3, 1) and 1.4826 MAD is a consistent estimate of a Gaussian's std; a
// polynomial of degree <= 2 has a zero third difference.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "diagnose/diagnose_noise.hpp"

namespace {

using rheomag::diagnose::noise_sigma;
using rheomag::diagnose::savitzky_golay;

/// A recording-like signal: a 1 Hz sine at 250 Hz plus current-like steps every 0.3 s.
std::vector<double> signal_with_steps(std::size_t n) {
  std::vector<double> y(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) / 250.0;
    y[k] = 3e6 * std::sin(2 * M_PI * t) + 1e6 * std::floor(std::fmod(t / 0.3, 3.0));
  }
  return y;
}

TEST(DiagnoseNoise, QuadraticHasNoNoise) {
  std::vector<double> y(500);
  for (std::size_t k = 0; k < y.size(); ++k) y[k] = 2.0 + 0.5 * k - 1e-3 * k * k;
  EXPECT_NEAR(noise_sigma(y), 0.0, 1e-9);
}

// Noise of 0.2 % and 1.5 % of the signal's spread on a sine with steps (the virtual rig's range):
// recovered within 10 % (the standard error of a MAD over 2 000 samples is about 2.6 %; the
// steps and the sine's curvature add a small bias).
TEST(DiagnoseNoise, WhiteNoiseUnderSineAndSteps) {
  for (double sigma : {5e3, 4e4}) {
    auto y = signal_with_steps(2000);
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0.0, sigma);
    for (double& v : y) v += noise(rng);
    EXPECT_NEAR(noise_sigma(y) / sigma, 1.0, 0.1) << sigma;
  }
}

// The cubic Savitzky-Golay smoother reproduces a cubic exactly (to rounding), and cuts white
// noise by sqrt(c0): a least-squares smoother is a projection, so the sum of the squared weights
// equals the centre weight, c0 = 3 (3M^2 + 3M - 1) / ((2M - 1)(2M + 1)(2M + 3)) for a quadratic or
// cubic over 2M + 1 points (the closed form of the quadratic/cubic Savitzky-Golay centre weight; M
// = 8: 645/4845, gain 0.365), checked within 3 % on 20 000 samples; its -3 dB bandwidth scales with
// the sample rate.
TEST(DiagnoseNoise, SavitzkyGolayKeepsCubicsAndCutsNoise) {
  std::vector<double> cubic(200);
  for (std::size_t k = 0; k < cubic.size(); ++k) {
    const double t = 0.01 * static_cast<double>(k);
    cubic[k] = 1.0 - 2.0 * t + 0.5 * t * t - 0.3 * t * t * t;
  }
  const auto kept = savitzky_golay(cubic, 0.01, 8);
  for (std::size_t k = 0; k < cubic.size(); ++k) EXPECT_NEAR(kept.values[k], cubic[k], 1e-9);
  std::vector<double> noise(20000);
  std::mt19937 rng(5);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (double& v : noise) v = unit(rng);
  const auto smooth = savitzky_golay(noise, 0.004, 8);
  double s2 = 0.0;
  for (std::size_t k = 8; k + 8 < noise.size(); ++k) s2 += smooth.values[k] * smooth.values[k];
  const double c0 = 3.0 * (3 * 64 + 3 * 8 - 1) / (15.0 * 17.0 * 19.0);
  EXPECT_NEAR(std::sqrt(s2 / static_cast<double>(noise.size() - 16)) / std::sqrt(c0), 1.0, 0.03);
  EXPECT_GT(smooth.bandwidth, 0.0);
  EXPECT_NEAR(savitzky_golay(noise, 0.005, 8).bandwidth / smooth.bandwidth, 0.8, 0.01);
}

}  // namespace
