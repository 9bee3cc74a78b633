// Time constant of a predicted field lag at a current.

#include "lumped/predicted_lag.hpp"

#include <algorithm>
#include <cmath>

namespace rheomag::lumped {

double PredictedLag::at(double i) const {
  const double a = std::abs(i);
  if (current.empty()) return 0.0;
  if (a <= current.front()) return time_constant.front();
  if (a >= current.back()) return time_constant.back();
  const auto k = static_cast<std::size_t>(std::upper_bound(current.begin(), current.end(), a) -
                                          current.begin());
  const double w = (a - current[k - 1]) / (current[k] - current[k - 1]);
  return (1.0 - w) * time_constant[k - 1] + w * time_constant[k];
}

}  // namespace rheomag::lumped
