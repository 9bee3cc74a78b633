#pragma once
// The rest a test starts from: the leading samples before the rig begins to move. Lab tests on a
// shaking table or a press often record a few seconds at rest before the motion starts; the force
// there is the load cell's zero (a tare that may differ from test to test), which a model compared
// with the recording must be given too.

#include <cstddef>
#include <vector>

namespace rheomag::lumped {

/// A sample is at rest while |motion| stays within this fraction of the motion's rms.
inline constexpr double kRestMotionFraction = 0.05;
/// A leading rest counts (leading_rest) only if it lasts at least this long ...
inline constexpr double kMinRestSeconds = 0.2;
/// ... and holds at least this many samples.
inline constexpr std::size_t kMinRestSamples = 10;
/// A shorter rest counts where the motion is exactly still, every leading sample equal to the
/// first (within the rest band), for at least this many samples: a rest beyond doubt however brief
/// (a velocity derived from a displacement that does not change is exactly 0), where a slow start
/// of the motion could otherwise pass for one.
inline constexpr std::size_t kMinStillSamples = 5;

/// Index of the first sample whose |motion| exceeds kRestMotionFraction of the motion's rms (the
/// start of the motion); 0 for a motion that is zero throughout or moves from the first sample.
std::size_t motion_start(const std::vector<double>& motion);

/// Number of leading samples at rest (motion_start) if they last at least kMinRestSeconds and
/// kMinRestSamples; else the leading samples exactly still, if at least kMinStillSamples; else 0.
std::size_t leading_rest(const std::vector<double>& t, const std::vector<double>& motion);

}  // namespace rheomag::lumped
