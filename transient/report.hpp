#pragma once
// Presenting a transient run: the JSON object of `rheomag transient --json` and a summary.

#include <nlohmann/json.hpp>
#include <string>

#include "transient/transient_solver.hpp"

namespace rheomag::transient {

/// Keys: drive, value, from, resistance, scheme, time, current, flux_linkage, eddy_power, gaps
/// [{name, B_avg, B_final, t63, t90, reduced_model}], final_current, final_flux_linkage, t63, t90
/// (null when not reached), reduced_model ({form, lags [{weight, time_constant}], delay,
/// max_error, rule, two_lag_fit}: transient::fit_reduced_model of the flux linkage), eddy_loss,
/// copper_loss, energy {...}, steps, rejected_steps, newton_iterations, factorizations, dofs,
/// seconds (SI units).
nlohmann::json transient_json(const TransientResult& result, const TransientOptions& options);

/// Error of lambda measured against half steps (relative to its change) above which a run of
/// equal steps is said not to resolve the response.
inline constexpr double kFixedStepErrorLimit = 0.01;

/// The warning of a run of equal steps whose estimated local error exceeds kFixedStepErrorLimit
/// ("" for adaptive steps or a resolved run).
std::string step_warning(const TransientResult& r, const TransientOptions& o);

/// Plain-text summary (ms, mWb, mT) with a short table of the response.
std::string transient_summary(const TransientResult& result, const TransientOptions& options);

}  // namespace rheomag::transient
