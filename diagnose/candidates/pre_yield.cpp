// The pre_yield candidate: the MR fluid's elastic pre-yield branch, a linear compliance between
// the chambers before the plug yields (it shows where the flow reverses and the plug re-forms).

#include <sstream>

#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_run.hpp"
#include "diagnose/diagnose_text.hpp"

namespace rheomag::diagnose::candidates {

namespace {

class PreYield final : public Candidate {
 public:
  std::string name() const override { return "pre_yield"; }

  bool applies(const DiagnosisModel& model) const override {
    // The pre-yield branch shows where the flow reverses and the plug re-forms.
    return !model.fitted_baseline() && model.baseline().kind != lumped::RigKind::coil_bench &&
           model.preyield_calibrated();
  }

  std::vector<ParamDef> params(const DiagnosisModel& model) const override {
    // Linear compliance per chamber [m^3/Pa], from the oil's own (V / 1.5 GPa) to that of a
    // 0.1 MPa gas (an elastic plug softer than any fluid column).
    const double bulk = lumped::ChamberBlock{}.bulk_modulus, oil = model.chamber_volume() / bulk;
    return {{"compliance", 100.0 * oil, oil, oil * bulk / 1e5, true, 1.0, "m^3/Pa"}};
  }

  void switch_on(lumped::RigSpec& spec, ParamReader& values,
                 const DiagnosisModel& model) const override {
    // A linear compliance between the chambers: the oil's bulk modulus softened to V / C (any
    // air of the compressibility candidate stays on top of it).
    const double compliance = values.next();
    if (!(compliance > 0.0)) return;
    lumped::ChamberBlock chamber = spec.compressibility.value_or(lumped::ChamberBlock{});
    chamber.oil_volume = model.chamber_volume();
    chamber.bulk_modulus = model.chamber_volume() / compliance;
    spec.compressibility = chamber;
  }

  std::string evidence(const Diagnosis& d, const ModelFit& fit) const override {
    std::ostringstream o;
    o << fmt(100 * regime_share(d.mismatch, "flow reversal"), 2)
      << " % of the residual energy sits at flow reversals, where the measured output rolls "
         "over smoothly instead of jumping with the Bingham map: the fluid deforms elastically "
         "before it yields; a linear compliance of "
      << fmt(fit_value(fit, "compliance"))
      << " m^3/Pa per chamber (the same at every amplitude, unlike air) explains it";
    return o.str();
  }

  bool uses_chamber_volume() const override { return true; }
};

}  // namespace

/// The pre_yield candidate (registered in candidate_registry.cpp).
const Candidate& pre_yield() {
  static const PreYield candidate;
  return candidate;
}

}  // namespace rheomag::diagnose::candidates
