#pragma once
// A prediction with one calibrated level per test: the gain and offset that map the model's
// prediction onto the measured output on the test's first steady cycle (least squares), scored on
// the rest of the test. Set against the pure prediction, it tells how much of a prediction's error
// is the test's level (e.g. its coil current or fluid temperature, which differ between tests) and
// how much is shape.

#include <cstddef>
#include <optional>
#include <vector>

namespace rheomag::identify {

/// Without a periodic drive, the calibration window is this fraction of the samples.
inline constexpr double kCalibrationFractionWithoutPeriod = 0.2;

/// One calibrated level of a prediction and its FIT after the calibration window.
struct LevelCalibration {
  double start_seconds = 0.0;     ///< [s] start of the window (its first steady cycle's)
  double seconds = 0.0;           ///< [s] length of the calibration window
  std::size_t samples = 0;        ///< samples in the calibration window
  double gain = 1.0;              ///< least-squares gain of the prediction on the window
  double offset = 0.0;            ///< [output unit] least-squares offset on the window
  double fit_percent = 0.0;       ///< FIT % of gain x prediction + offset after the window
  double pure_fit_percent = 0.0;  ///< FIT % of the prediction itself after the window
};

/// Calibrates `prediction` of the measured output y(t) under the drive v(t): gain and offset by
/// least squares on the first steady cycle of the motion (the first of steady_cycles(t, v) after
/// the motion's start, lumped::motion_start: a start-up ramp or overshoot, and the part cycle from
/// a rest, have a level of their own; where no steady cycle is found, from the motion's start to
/// the sample nearest to one drive_period(t, v) later; without a periodic drive, the first
/// kCalibrationFractionWithoutPeriod of the samples from the motion's start), both FITs on the
/// samples after it. Empty if the window or the rest holds fewer
/// than 2 samples, or the prediction is constant on the window (no gain to fit).
std::optional<LevelCalibration> calibrate_level(const std::vector<double>& t,
                                                const std::vector<double>& v,
                                                const std::vector<double>& y,
                                                const std::vector<double>& prediction);

}  // namespace rheomag::identify
