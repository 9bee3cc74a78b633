#include "optimise/response_check.hpp"

#include <cmath>

#include "design/response_time.hpp"

namespace rheomag::optimise {

ResponseCheck check_response_time(OptimiseEvaluator& evaluator, const OptimiseSpec& spec,
                                  OptimumState& state, double objective_scale,
                                  const IpoptSettings& settings, std::vector<HistoryRow>& history) {
  ResponseCheck out;
  for (;;) {
    const design::Quantities& q = state.rounded.quantities;
    design::ResponseTimeOptions o;
    o.supply_voltage = spec.supply_voltage;
    o.resistance = q[design::Quantity::resistance];
    o.time_constant = q[design::Quantity::time_constant];
    const design::ResponseTime full = design::response_time(*evaluator.last_field().solver,
                                                            evaluator.case_at(state.rounded.x), o);
    out.fe_solves += 2 * full.transient_runs;
    out.reduced = q[design::Quantity::response_time];
    out.transient = full.value();
    out.correction = evaluator.response_correction();
    if (std::abs(out.reduced / out.transient - 1.0) <= kResponseCheckTolerance ||
        out.rounds == kResponseRounds)
      return out;
    evaluator.set_response_correction(out.correction * out.transient / out.reduced);
    ++out.rounds;
    const ContinuousOptimum again = optimise_continuous(
        evaluator, spec, state.continuous.x, nullptr, objective_scale, settings, history);
    state.continuous = again.report;
    state.status = again.status;
    state.converged = again.converged;
    state.iterations += again.iterations;
    state.rounded = round_counts(evaluator, spec, again.report, history);
  }
}

}  // namespace rheomag::optimise
