// The residual of a prediction split by regime of the measured cycle: reversals, and the settled
// part of each stroke by its direction.

#include "identify/residual_regimes.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>

namespace rheomag::identify {

namespace {

enum class Regime { transition, positive, negative };

/// The direction of motion at every sample (+1 / -1), flipping only when the motion crosses the
/// band on the other side; samples before the first crossing take the first direction.
std::vector<int> stroke_directions(const std::vector<double>& motion, double band) {
  std::vector<int> dir(motion.size(), 0);
  int current = 0;
  for (std::size_t k = 0; k < motion.size(); ++k) {
    if (motion[k] > band) current = 1;
    if (motion[k] < -band) current = -1;
    dir[k] = current;
  }
  const auto first = std::find_if(dir.begin(), dir.end(), [](int d) { return d != 0; });
  const int initial = first == dir.end() ? 1 : *first;
  for (auto it = dir.begin(); it != first; ++it) *it = initial;
  return dir;
}

/// The median of `values` (not empty).
double median(std::vector<double> values) {
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

}  // namespace

std::optional<ResidualRegimes> residual_regimes(const std::vector<double>& motion,
                                                const std::vector<double>& measured,
                                                const std::vector<double>& prediction) {
  const std::size_t n = motion.size();
  if (n < 2 || measured.size() != n || prediction.size() != n) return std::nullopt;
  // The force about its mean: a load cell's offset (or a gas force) is not part of either stroke.
  const double level =
      std::accumulate(measured.begin(), measured.end(), 0.0) / static_cast<double>(n);
  double motion_ss = 0.0, power = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    motion_ss += motion[k] * motion[k];
    power += (measured[k] - level) * motion[k];
  }
  const auto [lo, hi] = std::minmax_element(motion.begin(), motion.end());
  if (!(*hi > *lo)) return std::nullopt;
  // The force opposes the motion or follows it, by the recording's sign convention.
  const double sign = power < 0.0 ? -1.0 : 1.0;
  const std::vector<int> dir =
      stroke_directions(motion, kReversalBandFraction * std::sqrt(motion_ss / n));

  std::vector<Regime> regime(n, Regime::transition);
  for (std::size_t begin = 0; begin < n;) {
    std::size_t end = begin;
    while (end < n && dir[end] == dir[begin]) ++end;
    // The force in the stroke's direction; the transition lasts until it settles.
    std::vector<double> along(end - begin);
    for (std::size_t k = begin; k < end; ++k)
      along[k - begin] = sign * dir[begin] * (measured[k] - level);
    const double settled = kSettledFraction * median(along);
    std::size_t k = begin;
    if (settled > 0.0)
      while (k < end && along[k - begin] < settled) ++k;
    else
      k = end;  // a force that never takes the stroke's direction never settles
    for (; k < end; ++k) regime[k] = dir[begin] > 0 ? Regime::positive : Regime::negative;
    begin = end;
  }

  ResidualRegimes out;
  double total = 0.0;
  std::size_t counts[3] = {0, 0, 0};
  double sums[3] = {0.0, 0.0, 0.0}, squares[3] = {0.0, 0.0, 0.0};
  for (std::size_t k = 0; k < n; ++k) {
    const auto r = static_cast<std::size_t>(regime[k]);
    const double e = prediction[k] - measured[k];
    ++counts[r];
    sums[r] += e;
    squares[r] += e * e;
    total += e * e;
  }
  RegimeResidual* parts[3] = {&out.transition, &out.positive, &out.negative};
  for (std::size_t r = 0; r < 3; ++r) {
    parts[r]->time_percent = 100.0 * static_cast<double>(counts[r]) / static_cast<double>(n);
    parts[r]->energy_percent = total > 0.0 ? 100.0 * squares[r] / total : 0.0;
    if (counts[r] > 0) {
      parts[r]->rms = std::sqrt(squares[r] / static_cast<double>(counts[r]));
      parts[r]->mean = sums[r] / static_cast<double>(counts[r]);
    }
  }
  return out;
}

}  // namespace rheomag::identify
