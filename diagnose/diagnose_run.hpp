#pragma once
// The diagnosis of one recording: calibrate the baseline, locate the mismatch, forward-select
// candidate physics (held-out blocks + BIC), re-fit all accepted effects together.

#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/progress.hpp"
#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_fit.hpp"
#include "diagnose/diagnose_locate.hpp"
#include "diagnose/diagnose_model.hpp"
#include "diagnose/reference_comparison.hpp"
#include "diagnose/size_sensitivity.hpp"
#include "identify/operating_range.hpp"
#include "lumped/metrics.hpp"
#include "lumped/recording.hpp"

namespace rheomag::diagnose {

/// Settings of the selection (defaults documented in docs/diagnosis.md).
struct DiagnoseOptions {
  int max_effects = 3;           ///< most effects forward selection may accept
  double bic_margin = 10.0;      ///< a candidate must lower BIC by more than this
  double heldout_margin = 0.03;  ///< ... and cut the held-out squared error by this fraction
  /// ... and remove this share of the residual energy above the noise floor (practical
  /// significance)
  double min_share = 0.1;
  /// ... and explain an output change at least this many noise standard deviations in rms over
  /// the recording: (SSE_now - SSE_new) >= min_noise_multiple^2 n sigma^2 (an effect smaller
  /// than the noise on every sample is not material, however well a long recording resolves it)
  double min_noise_multiple = 0.5;
  double max_relative_se = 0.5;  ///< ... with its size parameter identified to this rel. error
  int blocks = 8;                ///< alternating time blocks for the two-fold held-out check
  int max_iterations = 15;       ///< Levenberg-Marquardt iterations per fit
  ProgressCallback progress;     ///< told each stage and candidate fit with its time (or none)
  int threads = 2;               ///< threads for Jacobian columns, grid points and held-out folds
  /// Cost rule for long recordings: with more samples than this, candidates are screened,
  /// fitted and checked on this many consecutive samples (the stretch with the largest baseline
  /// residual energy); the baseline, the final joint re-fit and every reported FIT use all
  /// samples. 0: always the whole recording.
  std::size_t selection_samples = 15000;
  /// Start the fluid_inertia candidate also at the inertances the residual's ringing gives
  /// (diagnose_ringing.hpp) besides its decade grid; false: the grid alone (for comparison).
  bool ringing_start = true;
  /// Drive the states that remember the current's path (the Duhem candidate) by a noisy
  /// current's path estimate (current_path.hpp); false: by its samples (for comparison).
  bool current_path = true;
  /// Hold the output delay at 0 in the final fit where the data do not require it (BIC), so that
  /// an effect that is one force with the delay on the drive takes its whole size
  /// (diagnose_nuisances.hpp, align_unrequired_delay); false: the fitted delay kept (for
  /// comparison).
  bool align_delay = true;
  /// ... unless the free delay lowers BIC by more than this (2: "positive evidence" on Kass and
  /// Raftery's scale; a difference within the noise does not pick the end of a delay-effect valley)
  double align_delay_margin = 2.0;
  /// A fitted model as the baseline instead of the sidecar's rig (`--baseline MODEL.json`).
  std::optional<ModelBaseline> baseline_model;
  /// A recording of the same device to compare with (`--reference`): diagnosed against the same
  /// fitted-model baseline, and each effect linear in its size differenced (Diagnosis::reference).
  /// Needs `baseline_model`.
  std::optional<lumped::Recording> reference;
};

/// One candidate tried at one step of forward selection.
struct CandidateScore {
  const Candidate* effect = nullptr;  ///< a registered candidate (candidate_registry.hpp)
  int step = 0;
  double fit_percent = 0.0;
  double delta_bic = 0.0;  ///< BIC of the model before minus BIC with this candidate
  bool screened = false;   ///< no decade of its parameter helped: scored on the grid, not fitted
  /// Its own parameters as fitted at this step (SI; empty when screened): what a recording
  /// carries of it below the acceptance bar, e.g. to subtract from a later recording's finding.
  std::vector<std::string> param_names;
  std::vector<std::string> param_units;  ///< SI unit of each parameter
  std::vector<double> params;            ///< SI
  /// First step, a candidate linear in its size (Candidate::linear_in_size): its size against
  /// the baseline with the sign free (SI; negative: the recording has less of it than the
  /// baseline), and what derives from it. A finding on another recording minus this is the
  /// change between the two, also where this recording's own fit was screened out or held at
  /// its lower bound. Empty otherwise.
  std::vector<double> signed_params;
  std::vector<DerivedParam> signed_derived;
};

/// One accepted piece of missing physics.
struct Finding {
  const Candidate* effect;  ///< a registered candidate (candidate_registry.hpp)
  int step = 0;             ///< the forward-selection step that accepted it (0: the first)
  std::vector<std::string> param_names;
  std::vector<std::string> param_units;  ///< SI unit of each parameter ("1": dimensionless)
  std::vector<double> params;            ///< SI, from the final joint re-fit
  std::vector<double> standard_errors;   ///< SI
  /// Quantities derived from params (Candidate::derived_params, e.g. a damper's moving mass).
  std::vector<DerivedParam> derived;
  double fit_percent = 0.0;  ///< FIT% once this effect was added (selection stage)
  double delta_bic = 0.0;
  double heldout_gain = 0.0;  ///< fraction by which the held-out squared error fell
  double share = 0.0;         ///< share of the residual energy above the noise floor it removed
  std::string evidence;
  std::vector<const Candidate*>
      ambiguous_with;                  ///< candidates that explain the data almost equally
  std::string separating_measurement;  ///< what would tell them apart
  /// candidates that fit the output as well but not the measured coil current
  std::vector<const Candidate*> ruled_out_by_current;
  /// For an effect linear in its size: how its size trades with the output delay and with
  /// effects of the same shape on this drive (systematic, not in the standard error).
  SizeSensitivity sensitivity;
};

/// The nuisances calibrated in the baseline (never named as physics).
struct Nuisance {
  double delay = 0.0;          ///< [s] output behind the drives (negative: ahead)
  double delay_samples = 0.0;  ///< the same in sample intervals
  std::string sampling;        ///< the drive sampling convention and what the delay says
  DriveSampling drive_sampling = DriveSampling::linear;  ///< the convention calibrated
  /// FIT points the calibrated convention gains over the other (NaN: only one applies)
  double sampling_fit_gain = std::numeric_limits<double>::quiet_NaN();
  double preyield_flow = 0.0;  ///< [m^3/s] width of the static map's plug switch (0: not fitted)
  double preyield_fraction = 0.0;  ///< preyield_flow / peak flow
  /// The table map's knee: 0 the Bingham line, 1 the exact slit law (NaN: not calibrated)
  double slit_fraction = std::numeric_limits<double>::quiet_NaN();
  std::map<std::string, double> drive_noise;  ///< column -> white-noise std (SI)
  double velocity_filter_bandwidth = 0.0;     ///< [Hz] filter on a noisy velocity (0: none)
  /// [A] smallest swing of a noisy current that the Duhem candidate's path takes as a reversal
  /// (current_path.hpp; 0: the current as recorded)
  double current_reversal_band = 0.0;
  /// Motion drives repaired for single-sample acquisition glitches: column -> samples replaced
  std::map<std::string, std::size_t> motion_glitches;
};

/// What the residual of the final model still holds that no candidate explains.
struct Unexplained {
  double noise_sigma = 0.0;     ///< white-noise std of the output's residual (SI)
  double residual_rms = 0.0;    ///< rms residual of the final model (SI)
  double share = 0.0;           ///< share of the final residual energy above the noise floor
  double baseline_share = 0.0;  ///< the same energy as a share of the baseline's residual
};

/// The whole diagnosis.
struct Diagnosis {
  std::string recording;
  std::string output_column;     ///< the explained column ("pressure", "force", "current")
  std::vector<double> t;         ///< [s] sample times
  std::vector<double> measured;  ///< the measured output
  ModelFit baseline;
  double baseline_fit_percent = 0.0;
  std::vector<BaselineItem> includes;  ///< what the baseline contained
  Nuisance nuisance;                   ///< as calibrated in the baseline
  std::vector<MismatchWindow> mismatch;
  ResidualStats baseline_stats;
  std::vector<CandidateScore> candidates;  ///< scored on `selection` when it is not empty
  /// Samples the candidates were selected on (a long recording's excerpt; empty: all of them).
  lumped::SampleRange selection;
  std::vector<Finding> findings;
  ModelFit final_fit;
  double final_fit_percent = 0.0;
  ResidualStats final_stats;
  std::vector<MismatchWindow> final_mismatch;
  Nuisance final_nuisance;  ///< the nuisances as re-fitted with the findings
  Unexplained unexplained;
  /// A fitted-model baseline: what of the recording's drive lies beyond the drive it was fitted
  /// on (identify/operating_range.hpp); empty otherwise.
  std::vector<identify::RangeExcess> beyond_training;
  /// With DiagnoseOptions::reference: the reference's diagnosis summarised and the change of
  /// each linear effect from it to this recording.
  std::optional<ReferenceComparison> reference;
  std::vector<std::string> notes;
};

/// Diagnoses `rec` (its sidecar gives the baseline), and `options.reference` when given. Throws
/// InputError for a recording too short or too flat to say anything, a sidecar lacking what the
/// baseline needs, or a reference without a fitted-model baseline.
Diagnosis diagnose(const lumped::Recording& rec, const DiagnoseOptions& options = {});

/// The diagnosis in the fixed JSON format (shared/docs/recording-format.md) plus details.
nlohmann::json diagnosis_json(const Diagnosis& d);

}  // namespace rheomag::diagnose
