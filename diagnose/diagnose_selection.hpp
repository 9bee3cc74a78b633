#pragma once
// Forward selection of candidate physics on top of the calibrated baseline: each step fits every
// applicable candidate, ranks them by BIC and accepts the best that passes the rejection rules
// and the held-out check.

#include "diagnose/diagnose_clock.hpp"
#include "diagnose/diagnose_evidence.hpp"
#include "diagnose/diagnose_fit.hpp"
#include "diagnose/diagnose_run.hpp"

namespace rheomag::diagnose {

/// Forward selection on `model` from its calibrated baseline `current`: candidates are fitted,
/// tested and accepted one at a time (scores, findings and notes appended to `d`); returns the
/// fit of the last accepted model (`current` itself when nothing is accepted). `evidence` holds
/// the noise floor n sigma^2 of this model's baseline residual and the samples away from its
/// steps; ΔBIC, practical significance and the held-out gain are each met on every sample or
/// on the samples away from steps.
ModelFit forward_select(const DiagnosisModel& model, ModelFit current, const Evidence& evidence,
                        const DiagnoseOptions& options, Diagnosis& d, Clock& clock);

}  // namespace rheomag::diagnose
