// The neutral defaults of the Candidate interface.

#include "diagnose/candidate.hpp"

#include "core/error.hpp"

namespace rheomag::diagnose {

void Candidate::compose_with_model(FittedModelBlocks& /*blocks*/, ParamReader& /*values*/,
                                   const DiagnosisModel& /*model*/) const {
  throw InputError("diagnose: " + name() + " cannot be composed with a fitted-model baseline");
}

}  // namespace rheomag::diagnose
