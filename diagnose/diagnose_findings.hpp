#pragma once
// The text of a finding: its evidence sentence and what would tell it from a tied candidate.

#include <string>

#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_fit.hpp"
#include "diagnose/diagnose_run.hpp"

namespace rheomag::diagnose {

/// The evidence of finding `f` in `d` (Candidate::evidence), its values as in `fit`, with the
/// residual's strongest correlation and the candidates the measured coil current ruled out.
std::string finding_evidence(const Finding& f, const Diagnosis& d, const ModelFit& fit);

/// What would tell `a` from `b` when both explain the data almost equally: what either says
/// about the other (Candidate::separating_measurement), else a generic advice.
std::string separating_measurement(const Candidate& a, const Candidate& b);

}  // namespace rheomag::diagnose
