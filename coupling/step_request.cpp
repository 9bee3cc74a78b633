// A case's step response request (see step_request.hpp).

#include "coupling/step_request.hpp"

#include <cmath>

#include "core/error.hpp"
#include "valve/solved_valve.hpp"

namespace rheomag::coupling {

void check_step_request(const StepRequest& r) {
  if (r.current.has_value() == r.voltage.has_value())
    throw InputError("give exactly one of --current A or --voltage V");
  if (!(r.duration > 0.0) || !std::isfinite(r.duration))
    throw InputError("--duration: expected a time > 0 s");
  if (!std::isfinite(r.from)) throw InputError("--from: expected a finite current in A");
  if (r.resistance && (!(*r.resistance > 0.0) || !std::isfinite(*r.resistance)))
    throw InputError("--resistance: expected a resistance > 0 Ohm");
}

PreparedStep prepare_step(const cases::Case& c, const std::string& case_path,
                          const StepRequest& r) {
  check_step_request(r);
  if (c.problem.circuits.empty())
    throw InputError(case_path + ": the case has no circuit to drive");
  PreparedStep p{transient::transient_from_case(c), {}};
  p.options =
      transient::step_options(r.voltage ? transient::Drive::voltage : transient::Drive::current,
                              r.voltage ? *r.voltage : *r.current, r.duration);
  p.options.from_current = r.from;
  p.options.steps = r.steps;
  p.options.tolerance = r.tolerance;
  p.options.newton.max_iterations = r.newton_iterations;
  p.options.scheme = transient::kTimeSchemeNames.parse(r.scheme, "--scheme");
  // Coil resistance: the request's, else [transient] resistance, else from the winding's wire.
  std::optional<double> resistance = r.resistance;
  if (!resistance) resistance = p.set_up.case_options.resistance;
  if (!resistance) resistance = valve::wire_resistance(c, *p.set_up.statics);
  if (r.voltage && !resistance)
    throw InputError(case_path +
                     ": a voltage step needs the coil resistance: give the wire ([valve] wire = "
                     "\"AWG 24\"), [transient] resistance, or --resistance");
  p.options.resistance = resistance.value_or(0.0);
  p.options.progress = r.progress;
  return p;
}

}  // namespace rheomag::coupling
