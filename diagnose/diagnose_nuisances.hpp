#pragma once
// The baseline's nuisances (output delay, pre-yield smoothness) during selection: which are held
// while candidates are fitted, their re-calibration, their start values and their report.

#include <vector>

#include "diagnose/diagnose_fit.hpp"
#include "diagnose/diagnose_run.hpp"

namespace rheomag::diagnose {

/// The baseline's nuisances held (true) in the layout of `effects`: while candidates are
/// fitted and screened, the recording's timing and pre-yield smoothness stay as calibrated; the
/// held-out folds and the final joint re-fit free them (a fold fitted with them held can land
/// in another optimum and score a real effect as useless).
std::vector<bool> nuisances_held(const DiagnosisModel& model,
                                 const std::vector<const Candidate*>& effects);

/// Nuisances held while a candidate is screened and fitted: the pre-yield smoothness always;
/// the output delay only when the baseline put it at its bound (it was free to absorb a
/// candidate's phase, e.g. an inertia's lead or a compliance's lag, and is re-fitted with each
/// candidate so that the comparison is between two models each with its best delay; at a bound
/// it would make every step project onto the bound).
std::vector<bool> held_in_candidates(const DiagnosisModel& model,
                                     const std::vector<const Candidate*>& effects,
                                     const std::vector<double>& values);

/// Fits the candidate `effects` once more from `nominal` with the output delay free (`fit` was
/// fitted with it held at the bound the baseline put it at) and keeps that fit in `fit` when its
/// error is lower. A fit started at a bound projects every step onto it and can stall in a worse
/// optimum, so the delay is held there first; but the candidate may explain what pushed the delay
/// to its bound (on a sine, a mass's force and a delay's are nearly one waveform), and then only
/// the free fit can give the size back. Returns whether the free fit was kept; a free fit that
/// cannot be simulated leaves `fit` as it was.
bool keep_better_with_free_delay(const DiagnosisModel& model,
                                 const std::vector<const Candidate*>& effects,
                                 const std::vector<double>& nominal, const FitSettings& held,
                                 const std::vector<double>& starts, int threads, ModelFit& fit);

/// What holding the output delay at 0 in the final fit decided (align_unrequired_delay).
struct DelayAlignment {
  bool tried = false;      ///< the fitted delay was not 0 and the aligned fit could be simulated
  bool aligned = false;    ///< the aligned fit was kept
  double delay = 0.0;      ///< [s] the delay of the delayed fit it was compared with
  double delta_bic = 0.0;  ///< BIC the free delay lowers: n ln(SSE aligned / SSE delayed) - ln n
};

/// Holds `fit`'s output delay at 0 (the recording's channels aligned) and refits the rest from
/// `fit`'s values with `settings`, keeping that fit unless the free delay lowers BIC by more than
/// `margin` (n ln(SSE ratio) against ln n for its one parameter, the diagnosis's criterion): the
/// data do not require it. Where the delay and an effect are one force on the drive (a viscous
/// force's shift and a mass on a sinusoid) the fit can end anywhere along their valley, and the
/// delay, calibrated before any candidate, takes what its bounds allow of the effect; a margin
/// of a few units keeps a noise-sized BIC difference from choosing the valley's end. Where the
/// aligned fit is better than `fit`, `fit` stopped short of its optimum and is first refitted
/// from the aligned one with the delay free. If not aligned, `fit` is the better of the two
/// delayed fits; one that cannot be simulated leaves `fit` as it was (`tried` false).
DelayAlignment align_unrequired_delay(const DiagnosisModel& model, ModelFit& fit,
                                      const FitSettings& settings, double margin);

/// Re-calibrates the nuisances of `fit` that are not at a bound with everything else held (after
/// an accepted effect the pre-yield smoothing and delay it was compared with may no longer be
/// the best, and the next candidate would be credited with their gain).
void recalibrate_nuisances(const DiagnosisModel& model, ModelFit& fit, const FitSettings& base);

/// Sets `fit`'s output delay to its best value for the rest of its parameters (no refit).
void polish_delay(const DiagnosisModel& model, ModelFit& fit);

/// Static start values; the pre-yield smoothness (when calibrated) from a decade grid, since a
/// plug switch much narrower than a sample's flow step leaves the error flat in it.
std::vector<double> nuisance_start(const DiagnosisModel& model, int threads);

/// The nuisances of a fitted model.
Nuisance nuisance_of(const DiagnosisModel& model, const ModelFit& fit);

}  // namespace rheomag::diagnose
