#pragma once
// The change between two diagnoses of one device against the same fitted-model baseline: a
// reference recording (before a repair, last month) and today's. Each effect linear in its size
// is differenced, so what the reference already carried of it (the baseline's own mismatch on
// that device) is not counted as a change (docs/diagnosis.md, "Against a reference recording").

#include <string>

#include "diagnose/diagnose_run.hpp"
#include "diagnose/reference_comparison.hpp"

namespace rheomag::diagnose {

/// Differences `today` against `reference` (both diagnosed with the same baseline): for each
/// candidate sized on both (named, or with its sign free), today's size minus the
/// reference's; the reference's recording, baseline FIT and findings alongside.
ReferenceComparison compare_with_reference(const Diagnosis& today, const Diagnosis& reference);

/// One change as text, e.g. "friction: coulomb_force 40.2 N today (named), -0.3 N in the
/// reference (signed) -> change +40.5 N".
std::string change_text(const EffectChange& e);

/// The heading of the change list: which reference, its baseline FIT and its own findings.
std::string reference_heading(const ReferenceComparison& r);

}  // namespace rheomag::diagnose
