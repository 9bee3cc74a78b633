#pragma once
// The field lag of a valve predicted from its drawing: FE step responses with eddy currents
// (transient magnetics, docs/transient.md) reduced to a current-dependent first-order lag for
// the rigs' eddy_currents block.

#include <filesystem>
#include <vector>

namespace rheomag::lumped {

/// A first-order lag whose time constant depends on the current it is driven towards.
struct PredictedLag {
  std::vector<double> current;        ///< [A], increasing, > 0
  std::vector<double> time_constant;  ///< [s] at each current
  /// Time constant at |current| (linear interpolation, held beyond the ends).
  double at(double current) const;
};

/// For each current I (> 0, increasing): a current step 0 -> I on the first circuit of the FE
/// case at `case_path` (its conductivities and [transient] remedies), simulated until every
/// fluid gap's mean |B| has made 90 % of its change; the slowest gap's response is fitted by one
/// first-order lag (transient::fit_lags). InputError for a case that cannot be read or has no
/// conductivities / fluid gap, or bad currents; ConvergenceError when a step does not converge.
PredictedLag predict_field_lag(const std::filesystem::path& case_path,
                               const std::vector<double>& currents);

}  // namespace rheomag::lumped
