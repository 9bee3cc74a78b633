// The coil_heating candidate: the coil warms under its drive, its resistance R(T) rises and a
// voltage drive loses current (a slow drift).

#include <sstream>

#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_run.hpp"
#include "diagnose/diagnose_text.hpp"

namespace rheomag::diagnose::candidates {

namespace {

class CoilHeating final : public Candidate {
 public:
  std::string name() const override { return "coil_heating"; }

  bool applies(const DiagnosisModel& model) const override {
    // Only a voltage-driven coil loses current as it warms; inside the rig's electric loop, so
    // not a block on a fitted model.
    return !model.fitted_baseline() && model.baseline().driver_mode == lumped::DriverMode::voltage;
  }

  std::vector<ParamDef> params(const DiagnosisModel& model) const override {
    const auto& t = model.recording().t;
    const double duration = t.back() - t.front();
    return {{"thermal_resistance", 2.0, 1e-2, 1e3, true, 1.0, "K/W"},
            {"thermal_time_constant", duration, 1e-2 * duration, 1e3 * duration, true, 1.0, "s"}};
  }

  void switch_on(lumped::RigSpec& spec, ParamReader& values,
                 const DiagnosisModel& /*model*/) const override {
    lumped::ThermalBlock thermal;
    thermal.thermal_resistance = values.next();
    thermal.thermal_time_constant = values.next();
    spec.coil_heating = thermal;
  }

  std::string evidence(const Diagnosis& /*d*/, const ModelFit& fit) const override {
    std::ostringstream o;
    o << "the residual drifts slowly (it follows the integral of the coil drive); a coil "
         "warming with thermal resistance "
      << fmt(fit_value(fit, "thermal_resistance")) << " K/W and time constant "
      << fmt(fit_value(fit, "thermal_time_constant")) << " s loses current as R(T) rises";
    return o.str();
  }
};

}  // namespace

/// The coil_heating candidate (registered in candidate_registry.cpp).
const Candidate& coil_heating() {
  static const CoilHeating candidate;
  return candidate;
}

}  // namespace rheomag::diagnose::candidates
