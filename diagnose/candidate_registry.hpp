#pragma once
// The registered candidates (candidate_registry.cpp: one line per candidate) and the order in
// which they are tried on each kind of baseline.

#include <string_view>
#include <vector>

#include "diagnose/candidate.hpp"

namespace rheomag::diagnose {

/// Every registered candidate, in registration order.
const std::vector<const Candidate*>& registered_candidates();

/// The registered candidates in the order they are tried on a sidecar baseline (`fitted` false:
/// all of them) or on a fitted-model baseline (`fitted` true: those ranked there); forward
/// selection keeps this order among equally good fits, so it decides ties.
const std::vector<const Candidate*>& candidates_in_trial_order(bool fitted);

/// The registered candidates that apply to `model` (Candidate::applies), in trial order.
std::vector<const Candidate*> applicable_candidates(const DiagnosisModel& model);

/// The registered candidate called `name`; InputError when there is none.
const Candidate& candidate_named(std::string_view name);

}  // namespace rheomag::diagnose
