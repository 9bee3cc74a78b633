#pragma once
// A reduced model of a step response: a sum of first-order lags fitted to the FE response
// (for lumped models that need the field's dynamics without a field solve).

#include <vector>

namespace rheomag::transient {

/// One first-order lag of a reduced step response.
struct Lag {
  double weight = 0.0;         ///< share of the total change (the weights sum to 1)
  double time_constant = 0.0;  ///< [s]
};

/// Fits y(t) = end + (start - end) sum_k w_k exp(-t / tau_k), k = 1..count (1 to 3), sum w_k =
/// 1, to the samples (time, values) with t >= 0 (samples at t = 0 may be the value after an
/// instantaneous jump: they are fitted like the others). Variable projection: the weights by
/// linear least squares for given time constants, the log time constants by Levenberg-Marquardt
/// (Eigen). Lags sorted by time constant. InputError for count outside [1, 3], fewer than
/// 2 count + 1 samples, or end == start.
std::vector<Lag> fit_lags(const std::vector<double>& time, const std::vector<double>& values,
                          double start, double end, int count);

/// The reduced response at `t` [s] for lags fitted to a change from `start` to `end`.
double lag_response(const std::vector<Lag>& lags, double start, double end, double t);

}  // namespace rheomag::transient
