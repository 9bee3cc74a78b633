#pragma once
// Current-dependent grey-box fits across a family of recordings of one device (paper 001's
// protocol): one parameter set, with the field-scaled terms of the model linear in the current,
// fitted jointly on recordings at several currents and frequencies, then used to predict other
// recordings (e.g. another frequency), with per-recording metrics (RE of paper 001 eq. 10).

#include <optional>
#include <string>
#include <vector>

#include "identify/greybox.hpp"
#include "identify/level_calibration.hpp"
#include "identify/operating_range.hpp"
#include "identify/prediction_band.hpp"
#include "identify/residual_regimes.hpp"
#include "identify/viscosity_nuisance.hpp"
#include "lumped/metrics.hpp"
#include "lumped/recording.hpp"

namespace rheomag::identify {

/// Options of a family fit: the grey-box options plus how the recordings are joined.
struct FamilyFitOptions {
  GreyboxOptions greybox;  ///< `train` is ignored (every joined sample is fitted)
  int decimation = 4;      ///< keep every n-th sample of each recording in the joint fit
  /// Also refit once without each training recording and predict it (leave-one-recording-out).
  bool cross_validate = false;
  /// Levenberg-Marquardt iterations at most of each cross-validation refit, which starts (one
  /// start) from the fit of the half of the recordings without the held-out one (30: enough for
  /// the refits to converge, docs/performance.md); 0: every refit from the nominal start with the
  /// greybox options' starts and iterations (the cold refits of before).
  int refit_iterations = 30;
  /// Let each training recording's viscosity factor float within these bounds (a fitted
  /// nuisance for an unrecorded fluid temperature, identify/viscosity_nuisance.hpp); empty: off.
  std::optional<ViscosityNuisance> viscosity_nuisance;
  /// [s] Leads of the motion drive tried besides greybox.motion_lead, the one of lowest training
  /// cost kept (fit_family_searching_motion_lead; a cross-validation refit takes the lead of the
  /// half it starts from); empty (the library's default): greybox.motion_lead as given. The CLI
  /// and Python default to default_motion_leads().
  std::vector<double> motion_leads;
};

/// The family fit of `recs` with `greybox` (whose starts, holds and progress may differ from
/// options.greybox), searching the motion lead where options.motion_leads is not empty.
GreyboxFit fit_family(const std::vector<lumped::Recording>& recs, const std::string& model,
                      const GreyboxOptions& greybox, const FamilyFitOptions& options);

/// Metrics of the fitted model on one recording of the family (free run, full rate).
struct FamilyMember {
  std::string csv_path;
  double field = 0.0;  ///< [A or V] mean of the field drive column (the recording's current)
  lumped::Metrics metrics;
  /// The recording's output had its mean removed, so the model's was too (output_mean_removed).
  bool mean_removed = false;
  /// [s] The recording starts at rest for this long (lumped::leading_rest), so the model's output
  /// was tared to the recording's level there, as a load cell is zeroed before a test; 0: not.
  double rest_seconds = 0.0;
  /// Predicted recordings: the prediction's one-sigma band from the parameters' disagreement
  /// between the training recordings (prediction_band).
  std::optional<PredictionBand> band;
  /// FIT % of the recording's own mean cycle on its steady cycles, the most a model answering its
  /// periodic drive with a periodic output reaches there (repeatability_percent); empty if the
  /// drive is not periodic.
  std::optional<double> repeatability;
  /// Predicted and held-out recordings: the prediction with one level (gain and offset) fitted on
  /// the recording's first cycle and scored on the rest (calibrate_level); empty for the training
  /// recordings or where no calibration window exists.
  std::optional<LevelCalibration> level;
  /// Training recordings under FamilyFitOptions::viscosity_nuisance: the recording's fitted
  /// viscosity factor (geometric mean 1 over the training recordings); empty otherwise.
  std::optional<double> viscosity_factor;
  /// The model's residual on the recording by regime of its measured cycle (reversals, settled
  /// strokes in each direction; residual_regimes); empty where the motion is constant.
  std::optional<ResidualRegimes> regimes;
  std::vector<double> simulated;  ///< free-run model output at the recording's samples
  /// Predicted recordings: what of the recording's drive lies beyond the training recordings'
  /// (FamilyFit::trained); held-out recordings: beyond the other training recordings' (those
  /// its refit was fitted on); empty when within it.
  std::vector<RangeExcess> beyond;
};

/// Result of fit_current_dependent.
struct FamilyFit {
  GreyboxFit fit;                       ///< the joint fit (its metrics are on the joined data)
  std::vector<FamilyMember> training;   ///< the fitted model on each training recording
  std::vector<FamilyMember> predicted;  ///< the fitted model on each prediction recording
  /// Each training recording predicted by the family fitted without it, in training order
  /// (leave-one-recording-out, FamilyFitOptions::cross_validate); empty otherwise.
  std::vector<FamilyMember> held_out;
  /// The drive the training recordings span (written into the fitted model's JSON).
  OperatingRange trained;
};

/// The recordings joined end to end, each decimated by `decimation` and shifted in time to
/// follow the previous one by one (decimated) sample step; columns present in all are kept.
/// InputError if the list is empty, decimation < 1, or the recordings' sidecars disagree on the
/// drive or output columns.
lumped::Recording join_recordings(const std::vector<lumped::Recording>& recs, int decimation);

/// Checks that `training` and `prediction` make one family for `model`: InputError if empty, for
/// recordings of another rig kind or other drive/output columns, or for a field-dependent model
/// whose training recordings hold one field level only.
void check_family(const std::vector<lumped::Recording>& training,
                  const std::vector<lumped::Recording>& prediction, const std::string& model);

/// The fitted model `fit` on one recording: its free run at the recording's full rate and the
/// metrics against the recording's output (the band is left empty).
FamilyMember evaluate_family_member(const lumped::Recording& rec, const GreyboxFit& fit);

/// The fitted model `fit` predicting a recording it was not fitted on: evaluate_family_member
/// plus the prediction's band (prediction_band) and its calibrated level (calibrate_level).
FamilyMember predict_family_member(const lumped::Recording& rec, const GreyboxFit& fit);

/// Fits `model` (a grey-box name) jointly on `training` (joined, see join_recordings) so that its
/// field-scaled parameters are linear functions of the current, then simulates every training
/// and `prediction` recording separately with the fitted parameters; with
/// options.cross_validate, also fills held_out (cross_validate_family). InputError for a family
/// of mixed rigs or columns, or one field level for a field-dependent model.
FamilyFit fit_current_dependent(const std::vector<lumped::Recording>& training,
                                const std::string& model,
                                const std::vector<lumped::Recording>& prediction,
                                const FamilyFitOptions& options = {});

}  // namespace rheomag::identify
