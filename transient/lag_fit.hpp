#pragma once
// A reduced model of a step response: a sum of first-order lags fitted to the FE response
// (for lumped models that need the field's dynamics without a field solve).

#include <vector>

#include "core/enum_names.hpp"

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

/// The form of a reduced step response.
enum class ReducedForm {
  two_lags,        ///< y = end + (start - end) (w_1 e^(-t/tau_1) + w_2 e^(-t/tau_2))
  lag_with_delay,  ///< y = start for t < delay, end + (start - end) e^(-(t - delay)/tau) after
  /// a double lag: y = end + (start - end) (1 + shape t/tau) e^(-t/tau), the step response of
  /// (1 + (1 - shape) tau s) / (1 + tau s)^2 (shape 1: two equal lags in series); the limit of
  /// two lags whose time constants merge, in two well-conditioned numbers
  double_lag,
};

/// Text names of ReducedForm (JSON, text).
inline constexpr EnumNames<ReducedForm, 3> kReducedFormNames{
    {{{ReducedForm::two_lags, "two_lags"},
      {ReducedForm::lag_with_delay, "lag_with_delay"},
      {ReducedForm::double_lag, "double_lag"}}}};

/// Two lags are kept only when their time constants differ by at least this factor ...
inline constexpr double kMinLagSeparation = 3.0;
/// ... and no weight exceeds this magnitude (neither lag cancels the other).
inline constexpr double kMaxLagWeight = 2.0;

/// A well-conditioned reduced model of a step response (for a lumped model or Simulink).
struct ReducedModel {
  ReducedForm form = ReducedForm::two_lags;
  /// two_lags: two, sorted by time constant; lag_with_delay and double_lag: one (weight 1)
  std::vector<Lag> lags;
  double shape = 0.0;      ///< double_lag's shape (dimensionless; 0 for the other forms)
  double delay = 0.0;      ///< [s] dead time of lag_with_delay (0 for two_lags)
  double max_error = 0.0;  ///< largest |model - sample| over the samples / |end - start|
  /// The unconstrained two-lag fit that was tried first (kept for the record: why it was refused)
  std::vector<Lag> two_lag_fit;
};

/// Fits two lags (fit_lags) and keeps them when their time constants are at least
/// kMinLagSeparation apart and no |weight| exceeds kMaxLagWeight. Otherwise (two lags not
/// identifiable: near-equal time constants with large cancelling weights, the signature of two
/// lags in series such as a coil's L/R and a field lag) it fits one lag after a dead time (least
/// squares in the delay and the log time constant) and a double lag (the shape by linear least
/// squares, the log time constant by golden section) and keeps the one with the smaller largest
/// error. Same samples and InputErrors as fit_lags with count 2.
ReducedModel fit_reduced_model(const std::vector<double>& time, const std::vector<double>& values,
                               double start, double end);

/// The reduced model's response at `t` [s] for a change from `start` to `end`.
double reduced_response(const ReducedModel& model, double start, double end, double t);

}  // namespace rheomag::transient
