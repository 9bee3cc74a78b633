#include "optimise/response_check.hpp"

#include <cmath>

#include "design/response_time.hpp"

namespace rheomag::optimise {

double transient_response_time(OptimiseEvaluator& evaluator, const OptimiseSpec& spec,
                               const DesignReport& design, int* fe_solves,
                               const ProgressCallback& progress) {
  const design::Quantities& q = design.quantities;
  design::ResponseTimeOptions o;
  o.supply_voltage = spec.supply_voltage;
  o.resistance = q[design::Quantity::resistance];
  o.time_constant = q[design::Quantity::time_constant];
  o.progress = progress;
  const design::ResponseTime full =
      design::response_time(*evaluator.last_field().solver, evaluator.case_at(design.x), o);
  if (fe_solves) *fe_solves += 2 * full.transient_runs;  // the static states of each run
  return full.value();
}

ResponseCheck check_response_time(OptimiseEvaluator& evaluator, const OptimiseSpec& spec,
                                  OptimumState& state, double objective_scale,
                                  const IpoptSettings& settings, std::vector<HistoryRow>& history,
                                  const ProgressCallback& progress) {
  ResponseCheck out;
  for (;;) {
    out.reduced = state.rounded.quantities[design::Quantity::response_time];
    out.transient =
        transient_response_time(evaluator, spec, state.rounded, &out.fe_solves, progress);
    state.rounded.response_time_transient = out.transient;
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
