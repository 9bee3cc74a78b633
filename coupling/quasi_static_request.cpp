// A case's quasi-static step response (see quasi_static_request.hpp).

#include "coupling/quasi_static_request.hpp"

#include <algorithm>
#include <limits>

#include "core/error.hpp"
#include "core/format_text.hpp"
#include "transient/quasi_static.hpp"

namespace rheomag::coupling {

transient::QuasiStaticRun quasi_static_response(const cases::Case& c, const std::string& case_path,
                                                const StepRequest& request, int table_points) {
  if (table_points < 4) throw InputError("--table-points: expected a whole number >= 4");
  StepRequest r = request;
  r.duration = 1.0;  // no time stepping: a placeholder that passes the request's check
  const PreparedStep step = prepare_step(c, case_path, r);
  const transient::TransientOptions& options = step.options;
  const bool voltage = options.drive == transient::Drive::voltage;
  transient::QuasiStaticRun run;
  run.drive = voltage ? "voltage" : "current";
  run.value = options.value;
  run.from_current = options.from_current;
  run.final_current = voltage ? options.value / options.resistance : options.value;
  run.resistance = voltage ? options.resistance : 0.0;
  // A step to the steady state it starts from has no response (the table would span no range).
  if (run.final_current == run.from_current)
    throw InputError(voltage ? format_text("--voltage: %.6g V through %.6g Ohm holds the current "
                                           "at --from; expected a different voltage or --from",
                                           options.value, options.resistance)
                             : std::string("--current: the step goes to the current it starts "
                                           "from; expected a different --current or --from"));
  const double low = std::min({0.0, run.from_current, run.final_current});
  const double high = std::max({0.0, run.from_current, run.final_current});
  transient::TransientSolver& solver = *step.set_up.solver;
  run.table = transient::quasi_static_table(solver, low, high, table_points);
  run.step = transient::quasi_static_step(
      run.table, run.from_current, run.final_current,
      voltage ? options.resistance : std::numeric_limits<double>::infinity());
  const auto& regions = solver.statics().problem().geometry.regions;
  for (int g : run.table.gap_regions) run.gap_names.push_back(regions[g].name);
  run.dofs = solver.statics().dofs().free_count();
  return run;
}

}  // namespace rheomag::coupling
