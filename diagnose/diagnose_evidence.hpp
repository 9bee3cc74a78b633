#pragma once
// What a model's residual holds that no candidate can explain (the white noise floor, on every
// sample and on the samples away from steps), and what one effect of a model explains: its
// squared error switched off, and whether that is material.

#include <utility>
#include <vector>

#include "diagnose/diagnose_fit.hpp"
#include "diagnose/diagnose_run.hpp"

namespace rheomag::diagnose {

/// What no candidate can explain in a model's residual, on two sets of samples: every sample,
/// and the samples away from the steps of the baseline's prediction (away_from_steps), whose
/// values depend on the unrecorded sub-sample instant of a drive step. The white noise floor
/// n sigma^2 is counted on each set.
struct Evidence {
  std::vector<bool> away;   ///< samples away from steps (empty: every sample)
  double floor_all = 0.0;   ///< n sigma^2 on every sample
  double floor_away = 0.0;  ///< the same on the samples away from steps
};

/// The Evidence of a baseline prediction whose residual has white noise of deviation `sigma`.
Evidence evidence_of(const std::vector<double>& baseline_prediction, double sigma);

/// A squared error on every sample and on the samples away from steps (Evidence).
struct TwoSse {
  double all = 0.0, away = 0.0;
};

/// The squared error of `prediction` against `measured` on both sample sets of `e`.
TwoSse two_sse(const std::vector<double>& measured, const std::vector<double>& prediction,
               const Evidence& e);

/// Effects and parameter values of a model.
struct EffectSet {
  std::vector<const Candidate*> effects;
  std::vector<double> values;
};

/// `fit` with its i-th effect switched off (removed, every other parameter as fitted), and that
/// model's squared error on each sample set of `evidence` (infinite when it cannot be simulated).
std::pair<EffectSet, TwoSse> sse_switched_off(const DiagnosisModel& model, const ModelFit& fit,
                                              std::size_t i, const Evidence& evidence);

/// Whether removing `gain` from a residual of `sse` is material: at least `min_share` of the
/// energy above the noise floor `floor_sse` (the share is returned in `share`) and at least
/// `min_noise_multiple` noise deviations in rms (in `rms_in_sigma`).
bool material(double sse, double gain, double floor_sse, const DiagnoseOptions& options,
              double& share, double& rms_in_sigma);

}  // namespace rheomag::diagnose
