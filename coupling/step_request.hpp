#pragma once
// A step response asked of a case (the options of `rheomag transient`): checked, the coil
// resistance found (option, [transient] table or the [valve] wire) and the transient solver set
// up, ready to run. Shared by the CLI and the Python module.

#include <optional>
#include <string>

#include "case/case_file.hpp"
#include "core/progress.hpp"
#include "transient/from_case.hpp"
#include "transient/transient_options.hpp"

namespace rheomag::coupling {

/// What a step response is asked for; the messages name the CLI's options.
struct StepRequest {
  std::optional<double> current;     ///< current after the step [A] (or voltage)
  std::optional<double> voltage;     ///< supply voltage after the step [V]
  double from = 0.0;                 ///< current before the step (steady state) [A]
  double duration = 0.0;             ///< simulated time after the step [s]
  int steps = 0;                     ///< equal time steps; 0: adaptive
  double tolerance = 1e-4;           ///< adaptive steps' relative local error
  int newton_iterations = 50;        ///< per time step
  std::string scheme = "midpoint";   ///< or "backward_euler"
  std::optional<double> resistance;  ///< coil resistance [Ohm], overriding the case
  ProgressCallback progress;         ///< one report per accepted step; empty: none
};

/// InputError for a request that no case can satisfy (not exactly one of current and voltage, a
/// duration <= 0, a non-finite --from, a resistance <= 0).
void check_step_request(const StepRequest& request);

/// A step response ready to run: `set_up.solver->run(options, on_state)`.
struct PreparedStep {
  transient::CaseTransient set_up;
  transient::TransientOptions options;
};

/// Checks the request, sets the transient solver up on the case (`case_path` names it in
/// messages) and fills the options. InputError for a case without circuit or a voltage step
/// without a coil resistance.
PreparedStep prepare_step(const cases::Case& c, const std::string& case_path,
                          const StepRequest& request);

}  // namespace rheomag::coupling
