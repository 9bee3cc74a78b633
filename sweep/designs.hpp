#pragma once
// The designs of a sweep: a stable id (0 .. count-1) and the value of every axis key.

#include <vector>

#include "sweep/spec.hpp"

namespace rheomag::sweep {

/// One design: its id and one value per axis (same order as SweepSpec::axes).
struct Design {
  long long id = 0;
  std::vector<cases::KeyValue> values;
};

/// Generates designs deterministically. Factorial: id is the mixed-radix number of the level
/// indices (last axis fastest). Latin hypercube: for each axis in order, a permutation of the
/// strata 0..n-1 (Fisher-Yates with std::mt19937_64 seeded with `seed`, j = draw mod (i + 1))
/// then one uniform offset u = (draw >> 11) 2^-53 per design; design k takes
/// x = (stratum + u) / n, mapped to min + x (max - min) (rounded for integer keys) or to the
/// category floor(x * count). Same file, same designs, on every platform.
class DesignGenerator {
 public:
  explicit DesignGenerator(const SweepSpec& spec);
  /// Number of designs.
  long long count() const { return count_; }
  /// The design with this id (0 <= id < count()).
  Design design(long long id) const;

 private:
  const SweepSpec* spec_;
  long long count_ = 0;
  std::vector<std::vector<double>> unit_;  ///< Latin hypercube: [axis][design] in [0, 1)
};

}  // namespace rheomag::sweep
