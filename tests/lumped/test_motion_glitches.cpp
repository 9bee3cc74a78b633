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
#include "lumped/pheno_simulation.hpp"
#include "lumped/recording.hpp"

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

TEST(MotionGlitches, AGreyBoxModelReadsTheMotionWithoutItsGlitches) {
  // A damper test at 1 kHz: 1 s at rest, then a 1 Hz stroke of 9.5 mm (0.06 m/s peak); the
  // velocity is the displacement's exact derivative, the force a placeholder that varies.
  using namespace rheomag::lumped;
  Recording clean;
  clean.t = times(4000, 1000.0);
  auto& x = clean.columns["displacement"];
  auto& v = clean.columns["velocity"];
  auto& f = clean.columns["force"];
  for (double t : clean.t) {
    const double s = std::max(t - 1.0, 0.0);
    x.push_back(0.06 / (2.0 * M_PI) * std::sin(2.0 * M_PI * s));
    v.push_back(t > 1.0 ? 0.06 * std::cos(2.0 * M_PI * s) : 0.0);
    f.push_back(1e3 * v.back() + 50.0);
  }
  clean.meta.drive = {"displacement", "velocity"};
  clean.meta.output = "force";
  auto glitched = clean;
  glitched.columns["velocity"][300] = 0.05;  // a corrupted word while at rest
  glitched.columns["velocity"][2000] = 0.0;  // dropouts in motion
  glitched.columns["velocity"][3500] = 0.0;
  glitched.columns["displacement"][2700] = 0.0;
  const GreyboxSetup setup = greybox_setup_for(clean, PhenoKind::damper);
  const DriveSeries a = drive_series(clean, setup);
  const DriveSeries b = drive_series(glitched, setup);
  // Reference: the clean recording. A repaired sample is its neighbours' mean, within
  // v (1 - cos(2 pi f / rate)) = 1.2e-6 m/s of the sinusoid; its acceleration within 1.2e-3 m/s^2
  // of the clean one (peak 0.38 m/s^2; the glitch as recorded would make it 60 m/s^2); a
  // displacement sample within 9.5 mm (1 - cos(2 pi f / rate)) = 1.9e-7 m.
  for (std::size_t k = 0; k < a.t.size(); ++k) {
    ASSERT_NEAR(b.motion[k], a.motion[k], 2e-6) << "sample " << k;
    ASSERT_NEAR(b.acceleration[k], a.acceleration[k], 2e-3) << "sample " << k;
    ASSERT_NEAR(b.position[k], a.position[k], 3e-7) << "sample " << k;
  }
  // The rest the model's output is tared over is the clean recording's whole second.
  EXPECT_EQ(tared_rest(glitched, setup), tared_rest(clean, setup));
  EXPECT_EQ(b.rest_samples, a.rest_samples);
  EXPECT_GE(a.rest_samples, 990u);
}
