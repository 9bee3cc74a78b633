#pragma once
// A case's step response by the quasi-static reduction (`rheomag transient --quasi-static`,
// Python `case.transient(quasi_static=True)`): the request checked, the table of static states
// built over the step's currents and the rise times found, with no time stepping.

#include <string>

#include "case/case_file.hpp"
#include "coupling/step_request.hpp"
#include "transient/quasi_static_report.hpp"

namespace rheomag::coupling {

/// The quasi-static response to `request` on case `c` (`case_path` names it in messages).
/// Uses the request's current or voltage, from and resistance; its duration, steps, tolerance,
/// scheme and progress have no meaning here and are not used. `table_points` (>= 4): the table's
/// starting currents, equally spaced from 0 over the step's range. InputError for a bad request
/// or a step that does not change the current (naming --current or --voltage); ConvergenceError
/// when a static solve fails.
transient::QuasiStaticRun quasi_static_response(const cases::Case& c, const std::string& case_path,
                                                const StepRequest& request, int table_points);

}  // namespace rheomag::coupling
