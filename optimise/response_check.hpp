#pragma once
// response_model = "quasi_static": the reduction stands in for the two transient runs of every
// design; at the optimum the transient runs check it, and while they differ by more than 1 %
// the reduction is scaled by their ratio (output space mapping) and the optimisation repeated
// from that optimum.

#include <vector>

#include "core/progress.hpp"
#include "optimise/continuous.hpp"

namespace rheomag::optimise {

/// The bound (issue 35 point 2): the optimum's response_time within 1 % of the
/// transient runs' value.
inline constexpr double kResponseCheckTolerance = 0.01;
/// Most re-optimisations with a corrected reduction.
inline constexpr int kResponseRounds = 3;

/// The optimum's response_time by the (scaled) reduction and by the transient runs.
struct ResponseCheck {
  double reduced = 0.0;     ///< the reduction's value as the optimiser used it [s]
  double transient = 0.0;   ///< the two transient runs' value [s]
  double correction = 1.0;  ///< the factor on the reduction at the end
  int rounds = 0;           ///< re-optimisations with a corrected reduction
  int fe_solves = 0;        ///< static states of the checking transient runs
};

/// Where a continuous optimisation stands: its optimum before and after rounding counts, its
/// Ipopt status. Updated by check_response_time when it re-optimises.
struct OptimumState {
  DesignReport continuous, rounded;
  std::string status;
  bool converged = false;
  int iterations = 0;
};

/// The two transient runs' response_time of `design`, whose field is `evaluator`'s last.
/// `progress`: each transient step (design::ResponseTimeOptions::progress).
double transient_response_time(OptimiseEvaluator& evaluator, const OptimiseSpec& spec,
                               const DesignReport& design, int* fe_solves = nullptr,
                               const ProgressCallback& progress = {});

/// Checks `state.rounded` (whose field is `evaluator`'s last) by the transient runs; while they
/// differ from the reduction by more than kResponseCheckTolerance, at most kResponseRounds times,
/// scales the reduction by their ratio (OptimiseEvaluator::set_response_correction) and
/// optimises again from the continuous optimum. `progress`: each step of the transient runs.
ResponseCheck check_response_time(OptimiseEvaluator& evaluator, const OptimiseSpec& spec,
                                  OptimumState& state, double objective_scale,
                                  const IpoptSettings& settings, std::vector<HistoryRow>& history,
                                  const ProgressCallback& progress = {});

}  // namespace rheomag::optimise
