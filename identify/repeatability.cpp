// The FIT of a recording's own mean cycle on its steady cycles (repeatability.hpp).

#include "identify/repeatability.hpp"

#include <algorithm>
#include <cmath>

#include "lumped/output_smoothing.hpp"

namespace rheomag::identify {

namespace {

/// Linear interpolation of y at time tau (t increasing, t[0] <= tau <= t.back()).
double value_at(const std::vector<double>& t, const std::vector<double>& y, double tau) {
  const auto it = std::upper_bound(t.begin(), t.end(), tau);
  std::size_t j = static_cast<std::size_t>(it - t.begin());
  j = std::clamp<std::size_t>(j, 1, t.size() - 1) - 1;
  const double w = (tau - t[j]) / (t[j + 1] - t[j]);
  return y[j] + w * (y[j + 1] - y[j]);
}

/// The lower end of the steady cycles' band of drive swings: the band [s, s / 0.98] that holds
/// the most cycles (ties: the larger swings). The largest swing alone would make a start-up
/// overshoot (a first cycle a few % above the rest, as a shaking table's) the only steady cycle.
double steady_band_low(std::vector<double> swings) {
  std::sort(swings.begin(), swings.end());
  double best = 0.0;
  std::ptrdiff_t most = 0;
  for (auto first = swings.begin(); first != swings.end(); ++first) {
    const auto last = std::upper_bound(first, swings.end(), *first / 0.98);
    if (last - first >= most) {  // ties: the later, larger band
      most = last - first;
      best = *first;
    }
  }
  return best;
}

/// The FIT of the steady cycles' leave-one-cycle-out mean on each steady cycle's samples.
std::optional<double> mean_cycle_fit(const std::vector<double>& t, const std::vector<double>& y,
                                     const std::vector<DriveCycle>& steady) {
  const std::size_t n = steady.size();
  if (n < 3) return std::nullopt;
  double squared_error = 0.0, sum = 0.0, squares = 0.0, count = 0.0;
  for (std::size_t c = 0; c < n; ++c)
    for (std::size_t i = steady[c].begin; i < steady[c].end; ++i) {
      const double phase = (t[i] - steady[c].start) / (steady[c].stop - steady[c].start);
      double others = 0.0;
      for (std::size_t o = 0; o < n; ++o)
        if (o != c)
          others += value_at(t, y, steady[o].start + phase * (steady[o].stop - steady[o].start));
      const double e = y[i] - others / static_cast<double>(n - 1);
      squared_error += e * e;
      sum += y[i];
      squares += y[i] * y[i];
      count += 1.0;
    }
  const double spread = squares - sum * sum / count;
  if (!(spread > 0.0)) return std::nullopt;
  // The other cycles' mean carries noise of variance ~ (2/3) sigma^2 / (n - 1) (linear
  // interpolation of white noise at a uniform fraction), so E[e^2] ~ sigma^2 (1 + (2/3)/(n-1)).
  const double m = static_cast<double>(n - 1);
  return 100.0 * (1.0 - std::sqrt(squared_error * m / (m + 2.0 / 3.0) / spread));
}

}  // namespace

std::vector<DriveCycle> steady_cycles(const std::vector<double>& t, const std::vector<double>& v) {
  if (t.size() != v.size() || !(lumped::drive_period(t, v) > 0.0)) return {};
  const std::vector<double> crossings = lumped::upward_crossings(t, v);
  std::vector<DriveCycle> cycles;
  std::vector<double> swings;
  for (std::size_t k = 0; k + 1 < crossings.size(); ++k) {
    DriveCycle c;
    c.start = crossings[k];
    c.stop = crossings[k + 1];
    c.begin = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), c.start) - t.begin());
    c.end = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), c.stop) - t.begin());
    if (c.end <= c.begin) continue;
    const auto [lo, hi] = std::minmax_element(v.begin() + static_cast<std::ptrdiff_t>(c.begin),
                                              v.begin() + static_cast<std::ptrdiff_t>(c.end));
    swings.push_back(*hi - *lo);
    cycles.push_back(c);
  }
  const double low = steady_band_low(swings);
  std::vector<DriveCycle> steady;
  for (std::size_t k = 0; k < cycles.size(); ++k)
    if (swings[k] >= low && swings[k] <= low / 0.98) steady.push_back(cycles[k]);
  return steady;
}

std::optional<double> repeatability_percent(const std::vector<double>& t,
                                            const std::vector<double>& v,
                                            const std::vector<double>& y) {
  if (t.size() != v.size() || t.size() != y.size()) return std::nullopt;
  std::vector<DriveCycle> steady = steady_cycles(t, v);
  // Each sample is compared with every other cycle: a long test keeps kMaxCycles of its steady
  // cycles, evenly spread, so the cost stays kMaxCycles x samples.
  constexpr std::size_t kMaxCycles = 64;
  if (steady.size() > kMaxCycles) {
    std::vector<DriveCycle> spread;
    for (std::size_t k = 0; k < kMaxCycles; ++k)
      spread.push_back(steady[k * (steady.size() - 1) / (kMaxCycles - 1)]);
    steady = spread;
  }
  const std::optional<double> drive = mean_cycle_fit(t, v, steady);
  if (!drive || *drive < 95.0) return std::nullopt;  // the drive itself does not repeat
  return mean_cycle_fit(t, y, steady);
}

}  // namespace rheomag::identify
