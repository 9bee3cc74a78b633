// Drive period for the period-relative output smoothing (output_smoothing.hpp).

#include "lumped/output_smoothing.hpp"

#include <cmath>
#include <numeric>

namespace rheomag::lumped {

std::vector<double> upward_crossings(const std::vector<double>& t, const std::vector<double>& v) {
  const std::size_t n = std::min(t.size(), v.size());
  if (n < 4) return {};
  const double mean = std::accumulate(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n), 0.0) /
                      static_cast<double>(n);
  double ss = 0.0;
  for (std::size_t k = 0; k < n; ++k) ss += (v[k] - mean) * (v[k] - mean);
  const double band = 0.1 * std::sqrt(ss / static_cast<double>(n));
  if (!(band > 0.0)) return {};
  // An upward crossing counts once the signal has been below -band and then rises above +band;
  // its time is the last sign change of (v - mean) before that, linearly interpolated.
  std::vector<double> crossings;
  bool armed = false;
  double last_up = 0.0;
  for (std::size_t k = 1; k < n; ++k) {
    const double a = v[k - 1] - mean, b = v[k] - mean;
    if (a < 0.0 && b >= 0.0) last_up = t[k - 1] + (t[k] - t[k - 1]) * (-a) / (b - a);
    if (b < -band) armed = true;
    if (armed && b > band) {
      crossings.push_back(last_up);
      armed = false;
    }
  }
  return crossings;
}

double drive_period(const std::vector<double>& t, const std::vector<double>& v) {
  const std::vector<double> crossings = upward_crossings(t, v);
  if (crossings.size() < 3) return 0.0;
  const double period =
      (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  for (std::size_t k = 1; k < crossings.size(); ++k)
    if (std::abs(crossings[k] - crossings[k - 1] - period) > 0.2 * period) return 0.0;
  return period;
}

}  // namespace rheomag::lumped
