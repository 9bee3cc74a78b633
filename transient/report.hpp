#pragma once
// Presenting a transient run: the JSON object of `rheomag transient --json` and a summary.

#include <nlohmann/json.hpp>
#include <string>

#include "transient/transient_solver.hpp"

namespace rheomag::transient {

/// Keys: drive, value, from, resistance, scheme, time, current, flux_linkage, eddy_power, gaps
/// [{name, B_avg, B_final, t63, t90}], final_current, final_flux_linkage, t63, t90 (null when not
/// reached), eddy_loss, copper_loss, energy {...}, steps, rejected_steps, newton_iterations,
/// factorizations, dofs, seconds (SI units).
nlohmann::json transient_json(const TransientResult& result, const TransientOptions& options);

/// Plain-text summary (ms, mWb, mT) with a short table of the response.
std::string transient_summary(const TransientResult& result, const TransientOptions& options);

}  // namespace rheomag::transient
