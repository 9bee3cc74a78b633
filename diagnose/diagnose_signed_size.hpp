#pragma once
// A candidate's size against the baseline with its sign free: what a recording carries of it,
// more or less than the baseline has, so that two recordings' diagnoses can be differenced.

#include <vector>

#include "diagnose/diagnose_fit.hpp"
#include "diagnose/diagnose_run.hpp"

namespace rheomag::diagnose {

/// Fills `score.signed_params` (and `signed_derived`) of candidate `score.effect`, added to
/// `current` at the first step, when it is linear in its size on `model`
/// (Candidate::linear_in_size); leaves them empty otherwise. A candidate fitted inside its
/// bounds keeps its fitted size (the sign is not what held it); one screened out or fitted at its
/// lower bound is fitted again with the size on a linear scale within +-its upper bound, from
/// 0, the other parameters free or held as in `settings` (a delay held at its bound is also
/// tried free, the lower error kept). A fit that cannot be simulated leaves them empty.
void add_signed_size(const DiagnosisModel& model, const ModelFit& current,
                     const FitSettings& settings, CandidateScore& score);

}  // namespace rheomag::diagnose
