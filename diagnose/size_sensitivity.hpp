#pragma once
// What one recording cannot tell a named effect's size from: the model's own timing against the
// recording, and another effect whose force has the same shape on this drive (on one sinusoid a
// mass and a spring). The statistical standard error does not hold either: both are systematic.

#include <limits>
#include <string>
#include <vector>

#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_fit.hpp"
#include "diagnose/diagnose_model.hpp"

namespace rheomag::diagnose {

/// |correlation| of two effects' outputs from which the drive cannot tell them apart.
inline constexpr double kOneForce = 0.99;

/// Another effect linear in its size whose output has this one's shape on this drive.
struct ShapeTwin {
  const Candidate* effect = nullptr;  ///< the other effect
  std::string param;                  ///< its size parameter ("stiffness", ...)
  std::string unit;                   ///< SI unit of its size
  double correlation = 0.0;           ///< of the two outputs per unit size, means removed
  /// This effect's size (SI) whose output is the other's at one SI unit of its size, and what
  /// derives from it.
  double size_per_unit = 0.0;
  std::vector<DerivedParam> derived_per_unit;
  /// The other's size (SI) whose output is this effect's at its fitted size, and what derives
  /// from it (a spring's force as a moving mass); NaN where size_per_unit is 0.
  double same_force_at = std::numeric_limits<double>::quiet_NaN();
  std::vector<DerivedParam> same_force_derived;
};

/// How the size of a named effect linear in its size moves with what the recording cannot fix.
struct SizeSensitivity {
  /// [size's SI unit per s] change of the fitted size when the output delay is held later by
  /// one second, everything else refitted (measured over +-1 sample); NaN where not measured.
  double per_delay = std::numeric_limits<double>::quiet_NaN();
  std::vector<DerivedParam> derived_per_delay;  ///< the same for what derives from the size
  /// Linear effects whose output on this drive has this one's shape (|correlation| >= kOneForce).
  std::vector<ShapeTwin> twins;
};

/// The output of `fit`'s model per unit size of effect `c` (linear in its size), means removed:
/// two simulations, at `fit`'s values and with the size a tenth of its upper bound larger; an
/// effect that `fit` does not hold is added at size 0 with its other parameters nominal.
std::vector<double> unit_output_shape(const DiagnosisModel& model, const ModelFit& fit,
                                      const Candidate* c);

/// Inner product of two output shapes (over the shorter one's samples).
double shape_dot(const std::vector<double>& a, const std::vector<double>& b);

/// The size sensitivity of each effect of `fit` (in its order): for those linear in their size,
/// the output delay held one sample either side of its fitted value (inside its bounds) and
/// `fit` refitted from its values (at most `max_iterations`, sizes signed), and the candidates
/// among `linear_candidates` whose output shares its shape; empty for the others. A refit that
/// cannot be simulated leaves per_delay NaN.
std::vector<SizeSensitivity> size_sensitivities(
    const DiagnosisModel& model, const ModelFit& fit,
    const std::vector<const Candidate*>& linear_candidates, int max_iterations, int threads);

}  // namespace rheomag::diagnose
