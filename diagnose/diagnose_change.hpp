#pragma once
// The change between two diagnoses of one device against the same fitted-model baseline: a
// reference recording (before a repair, last month) and today's. Both are fitted once more with
// one set of effects (what either named, and every candidate linear in its size, those with the
// sign free), today's output delay held at the reference's, and each linear effect's sizes are
// differenced (docs/diagnosis.md, "Against a reference recording").

#include <string>

#include "diagnose/diagnose_model.hpp"
#include "diagnose/diagnose_run.hpp"
#include "diagnose/reference_comparison.hpp"

namespace rheomag::diagnose {

/// Compares `today` (diagnosed on `today_model`) with `reference` (on `reference_model`), both
/// against the same fitted baseline: each recording is fitted with the union of both recordings'
/// findings and the linear candidates applicable to both, from its own final fit, the linear
/// sizes with their sign free and today's output delay held at the reference's fitted one; the
/// change of each linear effect is today's size minus the reference's.
ReferenceComparison compare_with_reference(const DiagnosisModel& today_model,
                                           const Diagnosis& today,
                                           const DiagnosisModel& reference_model,
                                           const Diagnosis& reference,
                                           const DiagnoseOptions& options);

/// One change as text, e.g. "friction: coulomb_force 40.2 N today (named), -0.3 N in the
/// reference (signed) -> change +40.5 N".
std::string change_text(const EffectChange& e);

/// The heading of the change list: which reference, its baseline FIT and its own findings.
std::string reference_heading(const ReferenceComparison& r);

}  // namespace rheomag::diagnose
