#pragma once
// Locating a mismatch: time windows ranked by their share of the residual energy and tagged with
// the regime of the drive, and statistics of the residual (whiteness, correlation with the
// inputs, their derivatives and integrals, loops in (input, residual) planes).

#include <string>
#include <vector>

#include "lumped/recording.hpp"

namespace rheomag::diagnose {

/// One time window of the recording and its share of the residual energy.
struct MismatchWindow {
  std::size_t begin = 0, end = 0;  ///< sample range [begin, end)
  double t_start = 0.0, t_end = 0.0;
  double share = 0.0;  ///< fraction of the total squared residual in this window
  std::string regime;  ///< flow reversal, current rising edge, ... (see docs/diagnosis.md)
};

/// Windows of equal length ranked by residual share; the smallest set covering `cover` of the
/// energy (at most `max_windows`).
std::vector<MismatchWindow> locate_mismatch(const lumped::Recording& rec,
                                            const std::vector<double>& residual, int windows = 20,
                                            double cover = 0.6, std::size_t max_windows = 5);

/// Peak normalised cross-correlation of the residual with one signal.
struct SignalCorrelation {
  std::string signal;  ///< e.g. "velocity", "d/dt current", "integral velocity"
  double value = 0.0;  ///< correlation coefficient at the best lag
  double lag = 0.0;    ///< [s] positive: the residual follows the signal
};

/// Loop in the (input, residual) plane: its opening and whether it survives at slow rates.
struct ResidualLoop {
  std::string input;
  double opening = 0.0;          ///< |mean(r sign(du/dt))| / rms(r), 0 = no loop
  double slow_fast_ratio = 0.0;  ///< opening at the slowest third of |du/dt| / at the fastest
  bool rate_independent = false;
  /// |mean(r s)| / rms(r) over all samples, s = sign of the last change of u (held while u
  /// rests): a residual that remembers where u came from (hysteresis), 0 = no memory
  double memory_opening = 0.0;
};

/// Residual statistics of one model against the measurement.
struct ResidualStats {
  double lag1_autocorrelation = 0.0;
  double ljung_box_q = 0.0;  ///< over 20 lags
  bool white = false;        ///< Ljung-Box below the 1 % chi-square(20) point (37.57)
  std::vector<SignalCorrelation> correlations;  ///< strongest first
  std::vector<ResidualLoop> loops;
  double output_lag = 0.0;  ///< [s] shift of measured behind model maximising their correlation
};

/// Statistics of residual = measured - prediction against the recording's drive columns.
ResidualStats residual_statistics(const lumped::Recording& rec,
                                  const std::vector<std::string>& drive,
                                  const std::vector<double>& measured,
                                  const std::vector<double>& prediction);

}  // namespace rheomag::diagnose
