#include "sweep/designs.hpp"

#include <cmath>
#include <random>

namespace rheomag::sweep {

DesignGenerator::DesignGenerator(const SweepSpec& spec) : spec_(&spec), count_(design_count(spec)) {
  if (spec.method != SweepMethod::latin_hypercube) return;
  std::mt19937_64 engine(spec.seed);
  const auto n = static_cast<std::size_t>(count_);
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    std::vector<long long> strata(n);
    for (std::size_t i = 0; i < n; ++i) strata[i] = static_cast<long long>(i);
    for (std::size_t i = n; i-- > 1;) {
      const std::size_t j = static_cast<std::size_t>(engine() % (i + 1));
      std::swap(strata[i], strata[j]);
    }
    std::vector<double> unit(n);
    for (std::size_t k = 0; k < n; ++k) {
      const double u = static_cast<double>(engine() >> 11) * 0x1.0p-53;
      unit[k] = (static_cast<double>(strata[k]) + u) / static_cast<double>(n);
    }
    unit_.push_back(std::move(unit));
  }
}

Design DesignGenerator::design(long long id) const {
  Design d;
  d.id = id;
  const auto& axes = spec_->axes;
  d.values.resize(axes.size());
  if (spec_->method == SweepMethod::factorial) {
    long long rest = id;
    for (std::size_t a = axes.size(); a-- > 0;) {
      const auto n = static_cast<long long>(axes[a].levels.size());
      d.values[a] = axes[a].levels[static_cast<std::size_t>(rest % n)];
      rest /= n;
    }
    return d;
  }
  for (std::size_t a = 0; a < axes.size(); ++a) {
    const double x = unit_[a][static_cast<std::size_t>(id)];
    const SweepAxis& axis = axes[a];
    if (!axis.levels.empty()) {
      const auto n = axis.levels.size();
      const auto k = std::min(static_cast<std::size_t>(x * static_cast<double>(n)), n - 1);
      d.values[a] = axis.levels[k];
    } else {
      const double value = axis.lower + x * (axis.upper - axis.lower);
      if (axis.key.type == cases::KeyType::integer) {
        d.values[a] = static_cast<long long>(std::llround(value));
      } else {
        d.values[a] = value;
      }
    }
  }
  return d;
}

}  // namespace rheomag::sweep
