#pragma once
// The field lag of a valve predicted from its drawing: FE step responses with eddy currents
// (transient magnetics, docs/transient.md) reduced to a current-dependent first-order lag for
// the rigs' eddy_currents block (lumped/predicted_lag.hpp).

#include <filesystem>
#include <vector>

#include "lumped/predicted_lag.hpp"

namespace rheomag::coupling {

/// For each current I (> 0, increasing): a current step 0 -> I on the first circuit of the FE
/// case at `case_path` (its conductivities and [transient] remedies), simulated until every
/// fluid gap's mean |B| has made 90 % of its change; the slowest gap's response is fitted by one
/// first-order lag (transient::fit_lags). InputError for a case that cannot be read or has no
/// conductivities / fluid gap, or bad currents; ConvergenceError when a step does not converge.
lumped::PredictedLag predict_field_lag(const std::filesystem::path& case_path,
                                       const std::vector<double>& currents);

}  // namespace rheomag::coupling
