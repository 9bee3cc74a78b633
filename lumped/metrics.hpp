#pragma once
// Fit metrics used by fit/diagnose: FIT% (MATLAB compare), RMSE% (paper 000 eq. 6), RE (001 eq.
// 10).

#include <cstddef>
#include <span>
#include <string>

namespace rheomag::lumped {

/// A half-open range [begin, end) of sample indices of a recording.
struct SampleRange {
  std::size_t begin = 0;
  std::size_t end = 0;
  std::size_t size() const { return end - begin; }
};

/// Parses "a:b" (sample indices, half-open; "a:" means to the end, ":b" from 0) for a recording of
/// `n` samples; throws InputError naming `option` if malformed, empty or out of range.
SampleRange parse_sample_range(const std::string& text, std::size_t n, const std::string& option);

/// The three metrics of one comparison of measured `y` with model `yhat`.
struct Metrics {
  double fit_percent = 0.0;   ///< 100 (1 - ||y - yhat|| / ||y - mean(y)||)
  double rmse_percent = 0.0;  ///< 100 ||y - yhat|| / ||y - mean(y)||  (paper 000 eq. 6)
  double re = 0.0;            ///< sum|y - yhat| / sum|y|  (paper 001 eq. 10, a fraction)
};

/// FIT% = 100 (1 - ||y - yhat||_2 / ||y - mean(y)||_2); InputError if y is constant.
double fit_percent(std::span<const double> y, std::span<const double> yhat);

/// RMSE% of paper 000 eq. 6: 100 ||y - yhat||_2 / ||y - mean(y)||_2 (so RMSE% = 100 - FIT%).
double rmse_percent(std::span<const double> y, std::span<const double> yhat);

/// RE of paper 001 eq. 10: sum_i |y_i - yhat_i| / sum_i |y_i|; InputError if y is all zero.
double relative_error(std::span<const double> y, std::span<const double> yhat);

/// All three metrics of `yhat` against `y` (same length, at least 2 samples).
Metrics compute_metrics(std::span<const double> y, std::span<const double> yhat);

/// All three metrics on the samples of `range` only.
Metrics compute_metrics(std::span<const double> y, std::span<const double> yhat, SampleRange range);

}  // namespace rheomag::lumped
