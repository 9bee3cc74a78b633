// Gain and offset of a prediction fitted on a test's first steady cycle, scored on the rest
// (level_calibration.hpp).

#include "identify/level_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "identify/repeatability.hpp"
#include "lumped/leading_rest.hpp"
#include "lumped/metrics.hpp"
#include "lumped/output_smoothing.hpp"

namespace rheomag::identify {

std::optional<LevelCalibration> calibrate_level(const std::vector<double>& t,
                                                const std::vector<double>& v,
                                                const std::vector<double>& y,
                                                const std::vector<double>& prediction) {
  const std::size_t n = t.size();
  if (n < 4 || v.size() != n || y.size() != n || prediction.size() != n) return std::nullopt;
  // A test that starts at rest has no cycle there: nothing before the motion's start counts.
  std::size_t start = lumped::motion_start(v);
  const double period = lumped::drive_period(t, v);
  std::size_t window = 0;  // the window is [start, window)
  const std::vector<DriveCycle> steady = steady_cycles(t, v);
  const auto first = std::find_if(steady.begin(), steady.end(),
                                  [start](const DriveCycle& c) { return c.begin >= start; });
  if (first != steady.end()) {
    // The first steady cycle: a start-up (ramp, overshoot, the part cycle from rest) has a level
    // of its own.
    start = first->begin;
    window = first->end;
  } else if (period > 0.0) {
    // The samples before the one nearest to t[start] + period (the sampling need not divide it).
    const double end = t[start] + period;
    window = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), end) - t.begin());
    if (window > start && (window == n || end - t[window - 1] < t[window] - end)) --window;
  } else
    window = start + static_cast<std::size_t>(kCalibrationFractionWithoutPeriod *
                                              static_cast<double>(n - start));
  if (window < start + 2 || window > n || n - window < 2) return std::nullopt;
  // Least squares y ~ gain x prediction + offset on the window.
  const auto count = static_cast<double>(window - start);
  double mp = 0.0, my = 0.0;
  for (std::size_t i = start; i < window; ++i) {
    mp += prediction[i];
    my += y[i];
  }
  mp /= count;
  my /= count;
  double spp = 0.0, spy = 0.0;
  for (std::size_t i = start; i < window; ++i) {
    spp += (prediction[i] - mp) * (prediction[i] - mp);
    spy += (prediction[i] - mp) * (y[i] - my);
  }
  if (!(spp > 0.0)) return std::nullopt;
  LevelCalibration c;
  c.samples = window - start;
  c.start_seconds = t[start] - t.front();
  c.seconds = t[window] - t[start];
  c.gain = spy / spp;
  c.offset = my - c.gain * mp;
  std::vector<double> calibrated(prediction.begin() + static_cast<std::ptrdiff_t>(window),
                                 prediction.end());
  for (double& p : calibrated) p = c.gain * p + c.offset;
  const std::span<const double> rest(y.data() + window, n - window);
  c.fit_percent = lumped::compute_metrics(rest, calibrated).fit_percent;
  c.pure_fit_percent =
      lumped::compute_metrics(rest, std::span<const double>(prediction.data() + window, n - window))
          .fit_percent;
  return c;
}

}  // namespace rheomag::identify
