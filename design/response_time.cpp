#include "design/response_time.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "transient/from_case.hpp"
#include "transient/quasi_static.hpp"

namespace rheomag::design {

ResponseTime response_time(magnetostatics::MagnetostaticSolver& statics, const cases::Case& c,
                           const ResponseTimeOptions& options) {
  const std::string where = c.source.string();
  if (!(options.supply_voltage > 0.0) || !(options.resistance > 0.0) ||
      !(options.time_constant > 0.0) || options.steps < 1 || !(options.span_factor > 0.0))
    throw InputError(where + ": response_time needs supply_voltage > 0, a coil resistance and L/R");
  const transient::CaseTransient set_up = transient::transient_from_case(c, statics);
  ResponseTime out;
  const double final_current = options.supply_voltage / options.resistance;
  if (options.quasi_static) {
    const transient::QuasiStaticTable table = transient::quasi_static_table(
        *set_up.solver, 0.0, final_current, options.table_points, options.reuse);
    out.static_solves = static_cast<int>(table.points.size());
    auto slowest_gap = [&](double from, double to) {
      const transient::QuasiStaticStep step =
          transient::quasi_static_step(table, from, to, options.resistance);
      double slowest = 0.0;
      for (const std::optional<double>& t : step.gap_t90) {
        if (!t)
          throw ConvergenceError(where + ": response_time: in the quasi-static reduction the " +
                                 "gaps' mean |B| does not reach 90 % of its change");
        slowest = std::max(slowest, *t);
      }
      if (step.gap_t90.empty())
        throw InputError(where + ": response_time needs a fluid gap region");
      return slowest;
    };
    out.on = slowest_gap(0.0, final_current);
    out.off = slowest_gap(final_current, 0.0);
    return out;
  }
  auto slowest_gap_t90 = [&](double from_current, double voltage) {
    double span = options.span_factor * options.time_constant;
    for (int attempt = 0; attempt < 4; ++attempt, span *= 2.0) {
      transient::TransientOptions o =
          transient::step_options(transient::Drive::voltage, voltage, span);
      o.from_current = from_current;
      o.resistance = options.resistance;
      o.steps = options.steps;
      o.check_steps = false;         // a fixed cost per design; its accuracy is tested (docs)
      o.stop_at_gap_fraction = 0.9;  // t90 is all it reads: the steps after it change nothing
      if (options.progress)
        o.progress = [&](const ProgressEvent& e) {
          ProgressEvent step = e;
          step.stage = voltage > 0.0 ? "switch-on, % of its span" : "switch-off, % of its span";
          step.done = e.total > 0.0 ? 100.0 * e.done / e.total : 0.0;
          step.total = 100.0;
          step.total_is_bound = true;
          step.detail.clear();  // the run's own time left would mislead: it stops at t90
          options.progress(step);
        };
      const transient::TransientResult r = set_up.solver->run(o);
      ++out.transient_runs;
      double slowest = 0.0;
      bool reached = !r.gaps.empty();
      for (const transient::GapSeries& g : r.gaps) {
        if (!g.t90)
          reached = false;
        else
          slowest = std::max(slowest, *g.t90);
      }
      if (reached) return slowest;
    }
    throw ConvergenceError(where + ": response_time: the gaps' mean |B| did not reach 90 % of " +
                           "its change within " + std::to_string(span / 2.0) + " s");
  };
  out.on = slowest_gap_t90(0.0, options.supply_voltage);
  out.off = slowest_gap_t90(final_current, 0.0);
  return out;
}

}  // namespace rheomag::design
