// One calibrated level per predicted test (identify/level_calibration.hpp): gain and offset
// fitted on the first steady cycle, scored on the rest, against closed forms.

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "identify/level_calibration.hpp"

using namespace rheomag::identify;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Drive v = cos(2 pi t) (period 1 s; its upward crossings near 0.75 s + k) and output
/// y = sin(2 pi t) + 0.3 sin(6 pi t) (not a pure sine, so that a gain is not a phase), 200 samples
/// a second over `seconds`.
struct Signals {
  std::vector<double> t, v, y;
};

Signals periodic(double seconds) {
  Signals s;
  for (int k = 0; k < static_cast<int>(std::lround(200 * seconds)); ++k) {
    const double t = k / 200.0;
    s.t.push_back(t);
    s.v.push_back(std::cos(2 * kPi * t));
    s.y.push_back(std::sin(2 * kPi * t) + 0.3 * std::sin(6 * kPi * t));
  }
  return s;
}

/// FIT % (100 (1 - ||y - p|| / ||y - mean y||)) on the samples from `from` on, from its definition.
double fit_from(const std::vector<double>& y, const std::vector<double>& p, std::size_t from) {
  double mean = 0.0;
  for (std::size_t i = from; i < y.size(); ++i) mean += y[i];
  mean /= static_cast<double>(y.size() - from);
  double e = 0.0, spread = 0.0;
  for (std::size_t i = from; i < y.size(); ++i) {
    e += (y[i] - p[i]) * (y[i] - p[i]);
    spread += (y[i] - mean) * (y[i] - mean);
  }
  return 100.0 * (1.0 - std::sqrt(e / spread));
}

}  // namespace

// A prediction that is exactly gain x truth + offset (g = 1.25, o = 0.4): calibrated on the first
// steady cycle (from the drive's first upward crossing, 0.75 s, one period: 200 samples, within a
// sample) it is the truth, FIT 100 % (1e-9), with gain 1/g and offset -o/g (1e-12). The pure
// prediction's FIT on the samples after the window is the definition's on them (1e-9; 41.9 % on
// these 3.25 cycles, 40.33 % over whole ones: 100 (1 - sqrt(((g - 1)^2 m2 + o^2) / m2)), m2 =
// 0.545).
TEST(LevelCalibration, GainAndOffsetOfTheTruthAreRecovered) {
  const Signals s = periodic(5);
  const double g = 1.25, o = 0.4;
  std::vector<double> prediction;
  for (double y : s.y) prediction.push_back(g * y + o);
  const auto c = calibrate_level(s.t, s.v, s.y, prediction);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->start_seconds, 0.75, 0.006);
  EXPECT_NEAR(static_cast<double>(c->samples), 200.0, 1.0);
  EXPECT_NEAR(c->seconds, 1.0, 0.006);
  EXPECT_NEAR(c->gain, 1.0 / g, 1e-12);
  EXPECT_NEAR(c->offset, -o / g, 1e-12);
  EXPECT_NEAR(c->fit_percent, 100.0, 1e-9);
  const auto end = static_cast<std::size_t>(std::lround(c->start_seconds * 200)) + c->samples;
  EXPECT_NEAR(c->pure_fit_percent, fit_from(s.y, prediction, end), 1e-9);
}

// A test that starts with 2 s at rest (a shaking table that waits before it moves): the window is
// the first whole cycle of the motion, from its first upward crossing (2.75 s) for 200 samples
// (within a sample), not the rest. At rest the
// measured force carries sensor noise the model does not have (a flat prediction); a window there
// gave gains of -0.3 to 1e11 on shaking-table recordings. With the window on the motion the gain
// and offset of a prediction g x truth + o are inverted exactly (1e-12), as without the rest.
TEST(LevelCalibration, ATestThatStartsAtRestIsCalibratedOnItsFirstMovingCycle) {
  const Signals moving = periodic(5);
  Signals s;
  std::vector<double> prediction;
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.01);
  const double g = 1.25, o = 0.4;
  for (int k = 0; k < 400; ++k) {
    s.t.push_back(k / 200.0);
    s.v.push_back(0.0);
    s.y.push_back(noise(rng));
    prediction.push_back(o);
  }
  for (std::size_t k = 0; k < moving.t.size(); ++k) {
    s.t.push_back(2.0 + moving.t[k]);
    s.v.push_back(moving.v[k]);
    s.y.push_back(moving.y[k]);
    prediction.push_back(g * moving.y[k] + o);
  }
  const auto c = calibrate_level(s.t, s.v, s.y, prediction);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->start_seconds, 2.75, 0.006);
  EXPECT_NEAR(static_cast<double>(c->samples), 200.0, 1.0);
  EXPECT_NEAR(c->seconds, 1.0, 0.006);
  EXPECT_NEAR(c->gain, 1.0 / g, 1e-12);
  EXPECT_NEAR(c->offset, -o / g, 1e-12);
  EXPECT_NEAR(c->fit_percent, 100.0, 1e-9);
}

// A model error that is not a level (a phase lag of 0.05 cycle) stays after the calibration. A
// gain and offset cannot remove the part of each harmonic orthogonal to the truth's:
// sin(2 pi 0.05) = 0.309 of the fundamental, sin(6 pi 0.05) = 0.809 of the third harmonic, so the
// calibrated FIT is at most 100 (1 - sqrt((0.5 x 0.309^2 + 0.045 x 0.809^2) / 0.545)) = 62.36 %.
// It is never below the pure FIT on the same samples: least squares on the first cycle, and the
// rest repeats that cycle exactly.
TEST(LevelCalibration, AShapeErrorStays) {
  const Signals s = periodic(5);
  std::vector<double> prediction;
  for (double t : s.t)
    prediction.push_back(std::sin(2 * kPi * (t - 0.05)) + 0.3 * std::sin(6 * kPi * (t - 0.05)));
  const auto c = calibrate_level(s.t, s.v, s.y, prediction);
  ASSERT_TRUE(c.has_value());
  EXPECT_LT(c->fit_percent, 62.37);
  EXPECT_GE(c->fit_percent, c->pure_fit_percent - 1e-9);
}

// A start-up cycle with a level of its own (a shaking table's first cycle: its drive 6 % larger,
// the measured output 0.3 above its later level, as 0 V test 8 of the UTFPR tests, 139 N against
// 130 N; here up to 1.7 s) is not the calibration window: the next cycle is (from 1.75 s, within
// a sample), and a prediction that is the truth after the start-up keeps gain 1 and offset 0
// (1e-12), FIT 100 % (1e-9). Calibrated on the start-up cycle, the offset would carry its 0.3
// into every later cycle.
TEST(LevelCalibration, AStartUpCycleIsNotTheLevel) {
  Signals s = periodic(6);
  const std::vector<double> prediction = s.y;
  for (std::size_t k = 0; k < s.t.size(); ++k)
    if (s.t[k] < 1.7) {
      s.v[k] *= 1.06;
      s.y[k] += 0.3;
    }
  const auto c = calibrate_level(s.t, s.v, s.y, prediction);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->start_seconds, 1.75, 0.006);
  EXPECT_NEAR(c->gain, 1.0, 1e-12);
  EXPECT_NEAR(c->offset, 0.0, 1e-12);
  EXPECT_NEAR(c->fit_percent, 100.0, 1e-9);
}

// Without a periodic drive (white noise) the window is the first fifth of the samples; a
// constant prediction has no gain and too short a recording no window: none.
TEST(LevelCalibration, WindowWithoutAPeriodAndNone) {
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<double> t, v, y, prediction;
  for (int k = 0; k < 1000; ++k) {
    t.push_back(k * 0.01);
    v.push_back(n(rng));
    y.push_back(n(rng));
    prediction.push_back(2.0 * y.back() - 1.0);
  }
  const auto c = calibrate_level(t, v, y, prediction);
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->samples, 200u);
  EXPECT_NEAR(c->fit_percent, 100.0, 1e-9);
  EXPECT_FALSE(calibrate_level(t, v, y, std::vector<double>(t.size(), 3.0)).has_value());
  EXPECT_FALSE(calibrate_level({0.0, 1.0, 2.0}, {0.0, 1.0, 0.0}, {1.0, 2.0, 3.0}, {1.0, 2.0, 3.0})
                   .has_value());
}
