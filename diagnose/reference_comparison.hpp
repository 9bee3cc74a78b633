#pragma once
// What changed between a reference recording of a device and today's, both diagnosed against
// the same fitted-model baseline: each effect linear in its size, differenced (the types; the
// comparison is diagnose_change.hpp).

#include <string>
#include <vector>

#include "diagnose/candidate.hpp"

namespace rheomag::diagnose {

/// Another linear effect whose force has this one's shape on today's drive (on one sinusoid a mass
/// and a spring are one force, m a = -m w^2 x), and the two changes taken together.
struct SameForce {
  const Candidate* effect = nullptr;  ///< the other effect
  double correlation = 0.0;           ///< of the two forces' shapes on today's drive
  /// This effect's change plus the other's expressed in this effect's size (SI), and what
  /// derives from it.
  double combined_change = 0.0;
  std::vector<DerivedParam> combined_derived;
};

/// One effect's size on today's recording and on the reference, and their difference: both
/// from the comparison's joint fit of each recording (diagnose_change.hpp), the size with its
/// sign free (negative: less of it than the baseline has).
struct EffectChange {
  const Candidate* effect = nullptr;  ///< a registered candidate linear in its size
  std::string param;                  ///< its size parameter ("coulomb_force", ...)
  std::string unit;                   ///< SI unit of the size
  double today = 0.0;                 ///< SI
  bool named_today = false;           ///< today's diagnosis named it
  double reference = 0.0;             ///< SI
  bool named_reference = false;       ///< the reference's diagnosis named it
  double change = 0.0;                ///< today - reference (SI)
  /// What derives from the size (e.g. a moving mass), as today - reference.
  std::vector<DerivedParam> derived_change;
  /// Linear effects that the drive cannot tell from this one (|correlation| >= 0.99).
  std::vector<SameForce> same_force;
};

/// A reference recording's diagnosis, summarised, and the changes from it to today's.
struct ReferenceComparison {
  std::string recording;                  ///< the reference's CSV
  double baseline_fit_percent = 0.0;      ///< the baseline's FIT on the reference
  std::vector<std::string> findings;      ///< what its own diagnosis named
  std::vector<EffectChange> changes;      ///< each linear effect applicable to both
  std::vector<std::string> sized_on_one;  ///< linear effects applicable to only one of the two
  double reference_delay = 0.0;  ///< [s] the output delay fitted on the reference, held today
};

}  // namespace rheomag::diagnose
