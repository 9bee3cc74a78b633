#pragma once
// How far a fitted grey-box model's prediction moves with what the training recordings leave
// uncertain: the parameters' covariance between recordings propagated to the output, to first
// order (the delta method).

#include <optional>

#include "identify/greybox.hpp"
#include "lumped/recording.hpp"

namespace rheomag::identify {

/// The one-sigma band of a prediction over one recording.
struct PredictionBand {
  double rms = 0.0;      ///< [output unit] rms over the samples of sqrt(g_i^T C g_i)
  double percent = 0.0;  ///< rms as a percentage of the recording's output spread rms(y - mean y)
};

/// The band of `fit`'s output on `rec` from fit.covariance_between_recordings C, with g_i the
/// derivative of sample i's output by each parameter C covers (forward differences of a tenth of
/// its standard error; a parameter on a bound is left out: its error is not a two-sided one).
/// Empty when the fit has no covariance (one training recording).
std::optional<PredictionBand> prediction_band(const lumped::Recording& rec, const GreyboxFit& fit);

}  // namespace rheomag::identify
