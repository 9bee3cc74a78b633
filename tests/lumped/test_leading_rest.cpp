// The leading samples at rest of a recording (lumped/leading_rest.hpp): where the motion starts,
// and whether the rest before it is long enough to tare a load cell on.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "lumped/leading_rest.hpp"

using namespace rheomag::lumped;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// `rest` samples at rest, then a velocity sin(2 pi t) (period 1 s) for 5 s, at 100 Hz; the rest
/// carries velocity noise of `noise` (standard deviation).
struct Motion {
  std::vector<double> t, v;
};

Motion resting_then_sine(int rest, double noise) {
  Motion m;
  std::mt19937 rng(11);
  std::normal_distribution<double> n(0.0, noise > 0.0 ? noise : 1.0);
  for (int k = 0; k < rest + 500; ++k) {
    m.t.push_back(k / 100.0);
    const double moving = k < rest ? 0.0 : std::sin(2 * kPi * (k - rest) / 100.0);
    m.v.push_back(moving + (noise > 0.0 ? n(rng) : 0.0));
  }
  return m;
}

}  // namespace

// 1.5 s at rest: the motion starts where |v| first exceeds 5 % of its rms. The rms is that of the
// sine over the moving samples, 1/sqrt 2 scaled by sqrt(500 / 650); the sine exceeds
// 0.05 x 0.620 = 0.031 from its second sample (sin(2 pi 0.01) = 0.0628), so sample 151.
TEST(LeadingRest, RestBeforeASineEndsWhereTheMotionStarts) {
  const Motion m = resting_then_sine(150, 0.0);
  EXPECT_EQ(motion_start(m.v), 151u);
  EXPECT_EQ(leading_rest(m.t, m.v), 151u);
}

// Velocity noise of 0.5 % of the sine's amplitude (a derivative of a measured displacement)
// stays inside the 5 % band (0.031, six standard deviations): the rest is the same 151 samples
// (the sine's second sample, 0.0628, is above the band by more than six standard deviations).
TEST(LeadingRest, NoiseAtRestIsStillRest) {
  const Motion m = resting_then_sine(150, 0.005);
  EXPECT_EQ(leading_rest(m.t, m.v), 151u);
}

// A motion from the first samples, a noisy rest shorter than 0.2 s (10 samples at 100 Hz is 0.1 s)
// and a motion that is zero throughout have no rest to tare on.
TEST(LeadingRest, NoneWhenTooShortOrNoMotion) {
  const Motion moving = resting_then_sine(0, 0.0);
  EXPECT_EQ(motion_start(moving.v), 1u);
  EXPECT_EQ(leading_rest(moving.t, moving.v), 0u);
  const Motion brief = resting_then_sine(10, 0.005);
  EXPECT_EQ(leading_rest(brief.t, brief.v), 0u);
  const std::vector<double> t = {0.0, 0.1, 0.2, 0.3}, still(4, 0.0);
  EXPECT_EQ(motion_start(still), 0u);
  EXPECT_EQ(leading_rest(t, still), 0u);
  EXPECT_EQ(leading_rest({}, {}), 0u);
}

// A rest shorter than 0.2 s counts where the motion is exactly still (a velocity derived from a
// displacement that does not move is exactly 0; 0x87V test 8 of the UTFPR shaking table holds
// still for 6 samples, 0.06 s): from kMinStillSamples equal leading samples on. Exact: 10 zeros
// and the sine's first sample (sin 0 = 0) are 11 still samples; 4 zeros and sin 0 are 5, the
// least that counts; 3 and sin 0 are 4, which do not.
TEST(LeadingRest, AShortRestExactlyStillCounts) {
  const Motion brief = resting_then_sine(10, 0.0);
  EXPECT_EQ(leading_rest(brief.t, brief.v), 11u);
  const Motion least = resting_then_sine(static_cast<int>(kMinStillSamples) - 1, 0.0);
  EXPECT_EQ(leading_rest(least.t, least.v), kMinStillSamples);
  const Motion too_brief = resting_then_sine(static_cast<int>(kMinStillSamples) - 2, 0.0);
  EXPECT_EQ(leading_rest(too_brief.t, too_brief.v), 0u);
}
