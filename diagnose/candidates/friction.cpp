// The friction candidate: a Coulomb force of the damper's seals, stepping with the sign of the
// velocity.

#include <cmath>
#include <sstream>

#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_run.hpp"
#include "diagnose/diagnose_text.hpp"

namespace rheomag::diagnose::candidates {

namespace {

class Friction final : public Candidate {
 public:
  std::string name() const override { return "friction"; }

  bool applies(const DiagnosisModel& model) const override {
    // Only on a damper's force (a fitted model's needs the velocity it steps with).
    if (model.baseline().kind != lumped::RigKind::damper) return false;
    return !model.fitted_baseline() || model.recording().columns.count("velocity") > 0;
  }

  std::vector<ParamDef> params(const DiagnosisModel& model) const override {
    const double rms = model.output_spread();
    return {{"coulomb_force", 0.05 * rms, 1e-6 * rms, 10.0 * rms, true, 1.0, "N"}};
  }

  void switch_on(lumped::RigSpec& spec, ParamReader& values,
                 const DiagnosisModel& /*model*/) const override {
    spec.coulomb_force = values.next();
  }

  bool composes_with_fitted_model() const override { return true; }

  bool linear_in_size(const DiagnosisModel& model) const override {
    return model.fitted_baseline();  // a term added to the fitted model's output
  }

  void compose_with_model(FittedModelBlocks& blocks, ParamReader& values,
                          const DiagnosisModel& model) const override {
    const double force = blocks.sign * values.next();
    const auto& v = model.recording().column("velocity");
    for (std::size_t j = 0; j < v.size(); ++j)
      blocks.added_output[j] += force * std::tanh(v[j] / model.baseline().friction_velocity);
  }

  std::string evidence(const Diagnosis& d, const ModelFit& fit) const override {
    std::ostringstream o;
    double opening = 0.0, ratio = 0.0;
    for (const auto& l : d.baseline_stats.loops)
      if (l.input == "velocity") opening = l.opening, ratio = l.slow_fast_ratio;
    o << "the residual steps with the sign of the velocity (loop opening " << fmt(opening, 2)
      << " of the residual rms, " << fmt(ratio, 2) << " as wide at slow as at fast rates: "
      << (ratio > 0.5 ? "rate-independent" : "rate-dependent, so friction explains only part")
      << "); a Coulomb force of " << fmt(fit_value(fit, "coulomb_force")) << " N explains it";
    return o.str();
  }
};

}  // namespace

/// The friction candidate (registered in candidate_registry.cpp).
const Candidate& friction() {
  static const Friction candidate;
  return candidate;
}

}  // namespace rheomag::diagnose::candidates
