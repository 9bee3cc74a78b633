// Single-sample acquisition glitches in a measured motion (lumped/motion_glitches.hpp).
// References: the glitches planted, the clean signal they were planted in, and what must never
// count as one (a step, a quantised column's last digit, a dither at the sample rate, a jerk the
// displacement shows too).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "lumped/motion_glitches.hpp"

namespace {

using rheomag::lumped::find_motion_glitches;
using rheomag::lumped::without_glitches;

/// Sample times of n samples at `rate` [Hz].
std::vector<double> times(std::size_t n, double rate) {
  std::vector<double> t(n);
  for (std::size_t k = 0; k < n; ++k) t[k] = static_cast<double>(k) / rate;
  return t;
}

/// A 1 Hz velocity sinusoid of amplitude 0.06 m/s at 1 kHz, with white noise of 0.3 % of it.
std::vector<double> noisy_velocity(const std::vector<double>& t, unsigned seed) {
  std::mt19937 gen(seed);
  std::normal_distribution<double> noise(0.0, 0.003 * 0.06);
  std::vector<double> v(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) v[k] = 0.06 * std::cos(2.0 * M_PI * t[k]) + noise(gen);
  return v;
}

}  // namespace

TEST(MotionGlitches, PlantedGlitchesAreFoundExactlyAndRepairedToTheirPath) {
  const auto t = times(10000, 1000.0);
  const auto clean = noisy_velocity(t, 7);
  auto v = clean;
  // Dropouts to 0, a doubled value, a sign flip, and both ends: 15-100 % of the spread (0.12).
  const std::vector<std::size_t> planted = {0, 1500, 3001, 4550, 7020, 9999};
  v[0] = -0.02;
  v[1500] = 0.0;
  v[3001] *= 2.0;
  v[4550] = -v[4550];
  v[7020] = 0.0;
  v[9999] = 0.0;
  const auto found = find_motion_glitches(v, t);
  EXPECT_EQ(found.samples, planted);
  const auto repaired = without_glitches(v, found);
  for (std::size_t k : planted)  // within a few noise deviations (0.18 mm/s) of the clean value
    EXPECT_NEAR(repaired[k], clean[k], 1e-3) << "sample " << k;
  // Nothing else moves.
  for (std::size_t k = 1; k + 1 < v.size(); ++k) {
    if (std::find(planted.begin(), planted.end(), k) == planted.end()) {
      EXPECT_EQ(repaired[k], v[k]);
    }
  }
}

TEST(MotionGlitches, CleanNoisyMotionHasNone) {
  const auto t = times(100000, 1000.0);
  for (unsigned seed : {1u, 2u, 3u})
    EXPECT_TRUE(find_motion_glitches(noisy_velocity(t, seed), t).samples.empty());
}

TEST(MotionGlitches, StepsQuantisationAndDitherAreNotGlitches) {
  const auto t = times(4000, 1000.0);
  // A velocity of a stepped drive: constant levels with jumps between them.
  std::vector<double> steps(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) steps[k] = (k / 500) % 2 ? 0.05 : -0.05;
  EXPECT_TRUE(find_motion_glitches(steps, t).samples.empty());
  // A slow displacement quantised to 5 um (a last digit that flickers between two levels).
  std::vector<double> quantised(t.size());
  for (std::size_t k = 0; k < t.size(); ++k)
    quantised[k] = 5e-6 * std::round(0.01 * std::sin(0.2 * M_PI * t[k]) / 5e-6 +
                                     0.4 * std::sin(1.7 * static_cast<double>(k)));
  EXPECT_TRUE(find_motion_glitches(quantised, t).samples.empty());
  // A dither at the sample rate: every sample "leaves its path", so none is a glitch.
  std::vector<double> dither(t.size());
  for (std::size_t k = 0; k < t.size(); ++k)
    dither[k] = 0.05 * std::sin(2.0 * M_PI * t[k]) + (k % 2 ? 0.01 : -0.01);
  EXPECT_TRUE(find_motion_glitches(dither, t).samples.empty());
}

TEST(MotionGlitches, AVelocitySpikeTheDisplacementShowsIsMotion) {
  // A table that jerks: the displacement advances by 0.4 mm within one 10 ms interval and stays
  // there; its backward-difference velocity spikes for that one sample.
  const auto t = times(400, 100.0);
  std::vector<double> x(t.size()), v(t.size());
  for (std::size_t k = 0; k < t.size(); ++k)
    x[k] = 0.01 * std::sin(2.0 * M_PI * t[k]) + (k >= 150 ? 4e-4 : 0.0);
  for (std::size_t k = 1; k < t.size(); ++k) v[k] = (x[k] - x[k - 1]) / 0.01;
  v[0] = v[1];
  const auto alone = find_motion_glitches(v, t);
  ASSERT_EQ(alone.samples, std::vector<std::size_t>{150});  // read alone, it looks like one
  EXPECT_TRUE(find_motion_glitches(v, t, &x).samples.empty());
  // A velocity sample dropped to 0 where the displacement moves on is a glitch either way.
  auto dropped = v;
  dropped[100] = 0.0;
  EXPECT_EQ(find_motion_glitches(dropped, t, &x).samples, std::vector<std::size_t>{100});
}
