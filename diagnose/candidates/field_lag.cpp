// The first-order field lag shared by mr_response_time and eddy_currents.

#include "diagnose/candidates/field_lag.hpp"

#include <cmath>
#include <sstream>

#include "diagnose/diagnose_run.hpp"
#include "diagnose/diagnose_text.hpp"

namespace rheomag::diagnose::candidates {

std::vector<double> first_order_lag(const std::vector<double>& t, const std::vector<double>& u,
                                    double tau) {
  std::vector<double> y(u.size());
  if (u.empty()) return y;
  y[0] = u[0];
  for (std::size_t k = 0; k + 1 < u.size(); ++k) {
    const double h = t[k + 1] - t[k];
    const double e = std::exp(-h / tau);
    const double slope_tau = h > 0.0 ? (u[k + 1] - u[k]) / h * tau : 0.0;
    y[k + 1] = u[k + 1] - slope_tau + (y[k] - u[k] + slope_tau) * e;
  }
  return y;
}

bool FieldLag::applies(const DiagnosisModel& model) const {
  // On a fitted model: a lag of its field input, when it has one that moves.
  if (model.fitted_baseline()) return !model.field_column().empty() && !model.constant_field();
  return model.baseline().kind != lumped::RigKind::coil_bench;
}

std::vector<ParamDef> FieldLag::params(const DiagnosisModel& /*model*/) const {
  return {{"time_constant", 0.01, 1e-5, 10.0, true, 1.0, "s"}};
}

void FieldLag::compose_with_model(FittedModelBlocks& blocks, ParamReader& values,
                                  const DiagnosisModel& /*model*/) const {
  auto& r = blocks.inputs;
  r.columns[blocks.field_column] =
      first_order_lag(r.t, r.column(blocks.field_column), values.next());
}

std::string FieldLag::evidence(const Diagnosis& d, const ModelFit& fit) const {
  std::ostringstream o;
  const double edges = regime_share(d.mismatch, "current rising edge") +
                       regime_share(d.mismatch, "current falling edge");
  o << "the output lags the baseline by " << fmt(1e3 * d.baseline_stats.output_lag) << " ms"
    << (edges >= 0.5 ? ", mostly at current edges (" : " (") << fmt(100 * edges, 2)
    << " % of the residual energy in rising/falling-edge windows); a first-order lag of "
    << fmt(1e3 * fit_value(fit, "time_constant"))
    << " ms between current and yield stress removes it";
  return o.str();
}

double FieldLag::timing_lag(const DiagnosisModel& /*model*/, const ModelFit& fit) const {
  return fit.values[fit.layout.size() - 1];
}

}  // namespace rheomag::diagnose::candidates
