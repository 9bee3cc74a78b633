#pragma once
// The diagnosis of one recording: calibrate the baseline, locate the mismatch, forward-select
// candidate physics (held-out blocks + BIC), re-fit all accepted effects together.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/progress.hpp"
#include "diagnose/diagnose_fit.hpp"
#include "diagnose/diagnose_locate.hpp"
#include "diagnose/diagnose_model.hpp"
#include "lumped/recording.hpp"

namespace rheomag::diagnose {

/// Settings of the selection (defaults documented in docs/diagnosis.md).
struct DiagnoseOptions {
  int max_effects = 3;           ///< most effects forward selection may accept
  double bic_margin = 10.0;      ///< a candidate must lower BIC by more than this
  double heldout_margin = 0.03;  ///< ... and cut the held-out squared error by this fraction
  int blocks = 8;                ///< alternating time blocks for the two-fold held-out check
  int max_iterations = 15;       ///< Levenberg-Marquardt iterations per fit
  ProgressCallback progress;     ///< told each stage and candidate fit with its time (or none)
  int threads = 2;               ///< threads for Jacobian columns, grid points and held-out folds
};

/// One candidate tried at one step of forward selection.
struct CandidateScore {
  Effect effect;
  int step = 0;
  double fit_percent = 0.0;
  double delta_bic = 0.0;  ///< BIC of the model before minus BIC with this candidate
  bool screened = false;   ///< no decade of its parameter helped: scored on the grid, not fitted
};

/// One accepted piece of missing physics.
struct Finding {
  Effect effect;
  std::vector<std::string> param_names;
  std::vector<double> params;           ///< SI, from the final joint re-fit
  std::vector<double> standard_errors;  ///< SI
  double fit_percent = 0.0;             ///< FIT% once this effect was added
  double delta_bic = 0.0;
  double heldout_gain = 0.0;  ///< fraction by which the held-out squared error fell
  std::string evidence;
  std::vector<Effect> ambiguous_with;  ///< candidates that explain the data almost equally
  std::string separating_measurement;  ///< what would tell them apart
  /// candidates that fit the output as well but not the measured coil current
  std::vector<Effect> ruled_out_by_current;
};

/// The whole diagnosis.
struct Diagnosis {
  std::string recording;
  std::string output_column;     ///< the explained column ("pressure", "force", "current")
  std::vector<double> t;         ///< [s] sample times
  std::vector<double> measured;  ///< the measured output
  ModelFit baseline;
  double baseline_fit_percent = 0.0;
  std::vector<MismatchWindow> mismatch;
  ResidualStats baseline_stats;
  std::vector<CandidateScore> candidates;
  std::vector<Finding> findings;
  ModelFit final_fit;
  double final_fit_percent = 0.0;
  ResidualStats final_stats;
  std::vector<MismatchWindow> final_mismatch;
  std::vector<std::string> notes;
};

/// Diagnoses `rec` (its sidecar gives the baseline). Throws InputError for a recording too short
/// or too flat to say anything, or a sidecar lacking what the baseline needs.
Diagnosis diagnose(const lumped::Recording& rec, const DiagnoseOptions& options = {});

/// The diagnosis in the fixed JSON format (shared/docs/recording-format.md) plus details.
nlohmann::json diagnosis_json(const Diagnosis& d);

}  // namespace rheomag::diagnose
