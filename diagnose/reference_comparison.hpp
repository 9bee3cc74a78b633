#pragma once
// What changed between a reference recording of a device and today's, both diagnosed against
// the same fitted-model baseline: each effect linear in its size, differenced (the types; the
// comparison is diagnose_change.hpp).

#include <string>
#include <vector>

#include "diagnose/candidate.hpp"

namespace rheomag::diagnose {

/// One effect's size on today's recording and on the reference, and their difference. A size is
/// the named one (final joint re-fit) where the effect was named, else its size with the sign
/// free (CandidateScore::signed_params) beside what was named, or against the bare baseline when
/// nothing was: what the recording carries of it, more or less than the baseline has.
struct EffectChange {
  const Candidate* effect = nullptr;  ///< a registered candidate linear in its size
  std::string param;                  ///< its size parameter ("coulomb_force", ...)
  std::string unit;                   ///< SI unit of the size
  double today = 0.0;                 ///< SI
  bool named_today = false;           ///< today's size is a finding's (else the signed size)
  double reference = 0.0;             ///< SI
  bool named_reference = false;       ///< the reference's size is a finding's
  double change = 0.0;                ///< today - reference (SI)
  /// What derives from the size (e.g. a moving mass), as today - reference.
  std::vector<DerivedParam> derived_change;
};

/// A reference recording's diagnosis, summarised, and the changes from it to today's.
struct ReferenceComparison {
  std::string recording;                  ///< the reference's CSV
  double baseline_fit_percent = 0.0;      ///< the baseline's FIT on the reference
  std::vector<std::string> findings;      ///< what its own diagnosis named
  std::vector<EffectChange> changes;      ///< effects sized on both, in the candidates' order
  std::vector<std::string> sized_on_one;  ///< linear effects sized on only one of the two
};

}  // namespace rheomag::diagnose
