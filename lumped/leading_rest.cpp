// The leading samples at rest of a recording (leading_rest.hpp).

#include "lumped/leading_rest.hpp"

#include <algorithm>
#include <cmath>

namespace rheomag::lumped {

std::size_t motion_start(const std::vector<double>& motion) {
  if (motion.empty()) return 0;
  double squares = 0.0;
  for (double v : motion) squares += v * v;
  const double band = kRestMotionFraction * std::sqrt(squares / static_cast<double>(motion.size()));
  if (!(band > 0.0)) return 0;
  const auto first =
      std::find_if(motion.begin(), motion.end(), [band](double v) { return std::abs(v) > band; });
  return first == motion.end() ? 0 : static_cast<std::size_t>(first - motion.begin());
}

std::size_t leading_rest(const std::vector<double>& t, const std::vector<double>& motion) {
  const std::size_t n = std::min(t.size(), motion.size());
  if (n == 0) return 0;
  const std::size_t rest = motion_start(motion);
  if (rest >= kMinRestSamples && rest < n && t[rest] - t.front() >= kMinRestSeconds) return rest;
  std::size_t still = 1;
  while (still < n && motion[still] == motion.front()) ++still;
  return still >= kMinStillSamples && still <= rest ? still : 0;
}

}  // namespace rheomag::lumped
