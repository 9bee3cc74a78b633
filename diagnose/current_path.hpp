#pragma once
// The path of a noisy measured current for the states that remember it (the Duhem loop of
// magnetic_hysteresis): the current reverses only where it swings back by more than its white
// noise can, and between two reversals it is the least-squares monotone fit of the samples.

#include <cstddef>
#include <vector>

namespace rheomag::diagnose {

/// [A] Smallest swing taken as a reversal of a current with white noise `sigma` over `samples`
/// samples: 2 sigma sqrt(2 ln n), the largest rise or fall that white noise makes over n samples
/// with high probability (the universal threshold, twice: a maximum above and a minimum below).
double reversal_band(double sigma, std::size_t samples);

/// The path of `x` with reversals only where it swings back by more than `band`: each turning
/// point's plateau (the contiguous samples within `band` of its extreme) is its mean, and each
/// run between two plateaus the monotone least-squares fit (pool-adjacent-violators) of its
/// samples, bounded by the plateaus' levels. Zero phase; steps stay steps. Returns `x` unchanged
/// when `band` <= 0; a signal that never swings by more than `band` becomes its mean.
std::vector<double> current_path(const std::vector<double>& x, double band);

}  // namespace rheomag::diagnose
