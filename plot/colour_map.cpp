#include "plot/colour_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rheomag::plot {

namespace {

/// The ramp's anchor colours, evenly spaced over [0, 1].
constexpr std::array<Rgb, 5> kRamp{{{0.08, 0.06, 0.33},
                                    {0.13, 0.32, 0.74},
                                    {0.07, 0.62, 0.70},
                                    {0.45, 0.80, 0.32},
                                    {0.99, 0.91, 0.22}}};

/// The ramp at t in [0, 1], linear between anchors.
Rgb ramp(double t) {
  const double x = std::clamp(t, 0.0, 1.0) * (kRamp.size() - 1);
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(x), kRamp.size() - 2);
  const double f = x - static_cast<double>(i);
  const Rgb& a = kRamp[i];
  const Rgb& b = kRamp[i + 1];
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

}  // namespace

ColourMap::ColourMap(double low, double high, int bins) : low_(low), high_(high) {
  if (bins < 2 || !(high > low) || !std::isfinite(low) || !std::isfinite(high))
    throw std::invalid_argument("ColourMap: needs two or more bins and a finite low < high");
  colours_.reserve(bins);
  for (int i = 0; i < bins; ++i) colours_.push_back(ramp((i + 0.5) / bins));
}

int ColourMap::bin(double value) const {
  if (!(value > low_)) return 0;  // NaN too
  const double x = (value - low_) / bin_width();
  return std::min(bins() - 1, static_cast<int>(x));
}

int ColourMap::nearest_bin(Rgb c) const {
  int best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int i = 0; i < bins(); ++i) {
    const Rgb& k = colours_[i];
    const double d = std::pow(k.r - c.r, 2) + std::pow(k.g - c.g, 2) + std::pow(k.b - c.b, 2);
    if (d < best_distance) best_distance = d, best = i;
  }
  return best;
}

}  // namespace rheomag::plot
