// The mr_response_time candidate: the MR fluid's own response time, a first-order lag between
// the coil current and the yield stress.

#include "diagnose/candidates/field_lag.hpp"

namespace rheomag::diagnose::candidates {

namespace {

class MrResponseTime final : public FieldLag {
 public:
  std::string name() const override { return "mr_response_time"; }

  void switch_on(lumped::RigSpec& spec, ParamReader& values,
                 const DiagnosisModel& /*model*/) const override {
    spec.mr_response_time = values.next();
  }
};

}  // namespace

/// The mr_response_time candidate (registered in candidate_registry.cpp).
const Candidate& mr_response_time() {
  static const MrResponseTime candidate;
  return candidate;
}

}  // namespace rheomag::diagnose::candidates
