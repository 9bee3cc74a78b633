// The eddy_currents candidate: eddy currents in the core delay the flux behind the coil current,
// a first-order lag between current and yield stress.

#include "diagnose/candidates/field_lag.hpp"

namespace rheomag::diagnose::candidates {

namespace {

class EddyCurrents final : public FieldLag {
 public:
  std::string name() const override { return "eddy_currents"; }

  void switch_on(lumped::RigSpec& spec, ParamReader& values,
                 const DiagnosisModel& /*model*/) const override {
    spec.eddy_time_constant = values.next();
    spec.predicted_eddy_lag.reset();  // the fitted lag replaces a predicted one
  }

  std::string separating_measurement(const Candidate& other) const override {
    if (other.name() != "mr_response_time") return "";
    return "both are one first-order lag between coil current and yield stress; measure the "
           "flux in the gap (search coil or Hall probe): eddy currents delay the flux behind the "
           "current, a slow MR response does not; or repeat with a laminated core";
  }

  // The same lag block as mr_response_time in the rig model: while neither is in, this one's
  // fit would be that one's under another name.
  std::string same_block_as() const override { return "mr_response_time"; }
};

}  // namespace

/// The eddy_currents candidate (registered in candidate_registry.cpp).
const Candidate& eddy_currents() {
  static const EddyCurrents candidate;
  return candidate;
}

}  // namespace rheomag::diagnose::candidates
