// The residual by regime of the measured cycle (identify/residual_regimes.hpp), against closed
// forms on a force that settles exponentially after each reversal.
// Reference: a sinusoidal velocity v = sin(2 pi t / T) and a force that follows sign(v) through a
// first-order lag tau = T / 20 (periodic steady state: F = F0 (1 - 2 e^{-s / tau}) at s after a
// zero crossing, to e^{-10} = 5e-5). The force is monotone over a stroke, so its median is its
// value at the stroke's middle, F0 (1 - 2 e^{-5}); it reaches 0.9 of that at
// s* = -tau ln((1 - 0.9 (1 - 2 e^{-5})) / 2) = 2.8812 tau, and a stroke starts where v crosses
// the 5 %-of-rms band, asin(0.05 / sqrt 2) T / (2 pi) after the zero crossing. So the reversals
// hold (s* - that) / (T / 2) of the samples: 27.69 %. Tolerance 0.2 point (one sample of 1 000
// per cycle is 0.1 point).

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "identify/residual_regimes.hpp"

namespace {

using rheomag::identify::residual_regimes;

constexpr double kPi = 3.14159265358979323846;
constexpr int kPerCycle = 1000;
constexpr int kCycles = 10;

struct Cycle {
  std::vector<double> v, f;
};

/// The reference drive and force (period 1 s, force amplitude f0), in periodic steady state.
Cycle settling_force(double f0) {
  Cycle c;
  const double tau = 1.0 / 20.0;
  for (int k = 0; k < kPerCycle * kCycles; ++k) {
    const double t = static_cast<double>(k) / kPerCycle;
    c.v.push_back(std::sin(2.0 * kPi * t));
    const double half = std::fmod(t, 0.5);  // time since the last zero crossing
    const double sign = std::fmod(t, 1.0) < 0.5 ? 1.0 : -1.0;
    c.f.push_back(sign * f0 * (1.0 - 2.0 * std::exp(-half / tau)));
  }
  return c;
}

double expected_transition_percent() {
  const double tau = 1.0 / 20.0;
  const double median = 1.0 - 2.0 * std::exp(-0.25 / tau);
  const double settle = -tau * std::log((1.0 - 0.9 * median) / 2.0);
  const double band_delay = std::asin(0.05 / std::sqrt(2.0)) / (2.0 * kPi);
  return 100.0 * (settle - band_delay) / 0.5;
}

TEST(ResidualRegimes, ReversalsLastUntilTheForceSettles) {
  const Cycle c = settling_force(1000.0);
  std::vector<double> prediction = c.f;
  for (double& p : prediction) p += 1.0;  // a uniform error: energy shares equal time shares
  const auto g = residual_regimes(c.v, c.f, prediction);
  ASSERT_TRUE(g.has_value());
  EXPECT_NEAR(expected_transition_percent(), 27.69, 0.01);
  EXPECT_NEAR(g->transition.time_percent, expected_transition_percent(), 0.2);
  EXPECT_NEAR(g->transition.energy_percent, g->transition.time_percent, 1e-9);
  // The two directions hold the rest equally (the first stroke from t = 0 is a whole one).
  EXPECT_NEAR(g->positive.time_percent, g->negative.time_percent, 0.2);
  EXPECT_NEAR(g->transition.time_percent + g->positive.time_percent + g->negative.time_percent,
              100.0, 1e-9);
  EXPECT_NEAR(g->positive.mean, 1.0, 1e-12);
  EXPECT_NEAR(g->negative.rms, 1.0, 1e-12);
}

TEST(ResidualRegimes, ABiasByDirectionIsTold) {
  // A model that overshoots the positive force by 20 N and the negative one by -10 N. A settled
  // stroke's force has the stroke's sign throughout (also in its last samples, where the motion
  // has crossed zero but not yet the band), so each settled mean is exact.
  const Cycle c = settling_force(1000.0);
  std::vector<double> prediction = c.f;
  for (std::size_t k = 0; k < c.f.size(); ++k) prediction[k] += c.f[k] > 0.0 ? 20.0 : -10.0;
  const auto g = residual_regimes(c.v, c.f, prediction);
  ASSERT_TRUE(g.has_value());
  EXPECT_NEAR(g->positive.mean, 20.0, 1e-9);
  EXPECT_NEAR(g->negative.mean, -10.0, 1e-9);
  // Energy 400 : 100 per sample over equal times (to a sample of the stroke's 500).
  EXPECT_NEAR(g->positive.energy_percent / g->negative.energy_percent, 4.0, 0.03);
}

TEST(ResidualRegimes, ForceOppositeToTheMotionAndNoisyMotion) {
  // The same force with the other sign convention (force against the velocity, as mrdamper's),
  // and the motion with noise of 2 % of its amplitude: the band keeps noise from splitting
  // strokes, so the reversals stay at the closed form within 1 point.
  const Cycle c = settling_force(1000.0);
  std::vector<double> against = c.f, noisy = c.v;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.02 / 3.0);  // 3 sigma = 2 %
  for (std::size_t k = 0; k < c.f.size(); ++k) {
    against[k] = -c.f[k];
    noisy[k] += noise(rng);
  }
  std::vector<double> prediction = against;
  for (double& p : prediction) p += 1.0;
  const auto g = residual_regimes(noisy, against, prediction);
  ASSERT_TRUE(g.has_value());
  EXPECT_NEAR(g->transition.time_percent, expected_transition_percent(), 1.0);
}

TEST(ResidualRegimes, AForceOffsetIsNotADirection) {
  // The same force on a load cell that reads 300 N at rest (three tenths of the amplitude: the
  // force is then positive for most of the negative strokes): the regimes are those of the force
  // without the offset. Before the force was taken about its mean, every negative stroke stayed
  // in the reversals (measured on a shaking-table recording with a 100 N offset: 0 % negative).
  const Cycle c = settling_force(1000.0);
  std::vector<double> shifted = c.f, prediction = c.f;
  for (std::size_t k = 0; k < c.f.size(); ++k) {
    shifted[k] += 300.0;
    prediction[k] += 301.0;
  }
  const auto g = residual_regimes(c.v, shifted, prediction);
  ASSERT_TRUE(g.has_value());
  EXPECT_NEAR(g->transition.time_percent, expected_transition_percent(), 0.2);
  EXPECT_NEAR(g->positive.time_percent, g->negative.time_percent, 0.2);
  EXPECT_NEAR(g->negative.mean, 1.0, 1e-9);
}

TEST(ResidualRegimes, NoRegimesWithoutMotion) {
  const std::vector<double> still(100, 0.3), f(100, 1.0);
  EXPECT_FALSE(residual_regimes(still, f, f).has_value());
  EXPECT_FALSE(residual_regimes({0.0, 1.0}, {1.0}, {1.0, 2.0}).has_value());
  EXPECT_FALSE(residual_regimes({}, {}, {}).has_value());
}

}  // namespace
