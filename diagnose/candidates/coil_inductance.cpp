// The coil_inductance candidate: the coil's inductance, an L/R lag of the current behind a
// voltage drive; where the sidecar states an inductance, the inductance beyond it.

#include <sstream>

#include "diagnose/candidates/field_lag.hpp"
#include "diagnose/diagnose_fit.hpp"
#include "diagnose/diagnose_run.hpp"
#include "diagnose/diagnose_text.hpp"

namespace rheomag::diagnose::candidates {

namespace {

class CoilInductance final : public Candidate {
 public:
  std::string name() const override { return "coil_inductance"; }

  bool applies(const DiagnosisModel& model) const override {
    // A stated inductance is in the baseline already; an inductance beyond it is in series with
    // it, one L/R lag of the summed inductance, which a field lag behind the stated coil's lag
    // (two lags in series) is not.
    const bool stated = model.baseline().coil.inductance > 0.0;
    if (!model.fitted_baseline())
      return model.baseline().driver_mode == lumped::DriverMode::voltage;
    // On a fitted model: the coil's L/R lag of a voltage field input (its resistance stated). A
    // model fitted to a coil with a stated inductance holds that coil's lag in its own response,
    // so an inductance beyond it would be one more lag of the field input: a field lag.
    const std::string& field = model.field_column();
    return !field.empty() && !model.constant_field() && field != "current" &&
           field != "current_cmd" && model.recording().meta.coil.resistance && !stated;
  }

  std::vector<ParamDef> params(const DiagnosisModel& /*model*/) const override {
    return {{"inductance", 0.1, 1e-5, 100.0, true, 1.0, "H"}};
  }

  void switch_on(lumped::RigSpec& spec, ParamReader& values,
                 const DiagnosisModel& /*model*/) const override {
    spec.coil.inductance += values.next();  // beyond the stated inductance (0 if none)
  }

  bool composes_with_fitted_model() const override { return true; }

  void compose_with_model(FittedModelBlocks& blocks, ParamReader& values,
                          const DiagnosisModel& model) const override {
    auto& r = blocks.inputs;
    r.columns[blocks.field_column] = first_order_lag(
        r.t, r.column(blocks.field_column), values.next() / model.baseline().coil.resistance_20c);
  }

  std::string evidence(const Diagnosis& d, const ModelFit& fit) const override {
    std::ostringstream o;
    // The coil resistance: fitted on a coil bench, else as the sidecar states it.
    double resistance = fit_value(fit, "coil_resistance");
    for (const BaselineItem& item : d.includes)
      if (resistance <= 0.0 && item.name == "coil_resistance") resistance = item.value;
    double stated = 0.0;
    for (const BaselineItem& item : d.includes)
      if (item.name == "coil_inductance") stated = item.value;
    const double inductance = fit_value(fit, "inductance"), total = stated + inductance;
    o << "the response lags the coil voltage at its edges (output "
      << fmt(1e3 * d.baseline_stats.output_lag) << " ms behind the baseline); an inductance of "
      << fmt(inductance) << " H";
    if (stated > 0.0)
      o << " beyond the stated " << fmt(stated) << " H (" << fmt(total) << " H in all)";
    if (resistance > 0.0) o << " (L/R = " << fmt(1e3 * total / resistance) << " ms)";
    o << " explains it";
    return o.str();
  }

  std::string separating_measurement(const Candidate& other) const override {
    if (other.name() != "eddy_currents" && other.name() != "mr_response_time") return "";
    return "record the coil current: inductance delays the current itself, field and fluid lags "
           "do not";
  }

  double timing_lag(const DiagnosisModel& model, const ModelFit& fit) const override {
    // Fitted to the coil current itself (the output of a coil bench), the L/R lag is the only
    // dynamics between the recorded voltage and the recorded output, and its exponential
    // approach after each step is not a shift (a delay moves the whole step; the lag's
    // remainder decays over the following samples at a rate the step heights fix).
    if (model.output_column() == "current") return 0.0;
    return fit.values[fit.layout.size() - 1] /
           model.spec(fit.effects, fit.values).coil.resistance_20c;
  }
};

}  // namespace

/// The coil_inductance candidate (registered in candidate_registry.cpp).
const Candidate& coil_inductance() {
  static const CoilInductance candidate;
  return candidate;
}

}  // namespace rheomag::diagnose::candidates
