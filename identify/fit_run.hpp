#pragma once
// The workflow of `rheomag fit`: one model (black-box, grey-box or valve-chain) fitted on the
// training part of a recording and checked on a validation part or another recording, with the
// JSON document and the text report of the result (the CLI only parses options and prints).

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "core/progress.hpp"
#include "identify/black_box_model.hpp"
#include "identify/greybox.hpp"
#include "identify/operating_range.hpp"
#include "identify/stability.hpp"
#include "lumped/metrics.hpp"
#include "lumped/recording.hpp"

namespace rheomag::identify {

/// What a fit is asked for (the options of `rheomag fit`).
struct FitRequest {
  std::string recording;  ///< recording CSV (its sidecar beside it)
  std::string model;      ///< a black-box spec (arx:..., tf:..., ...), grey-box name or valve-chain
  std::string train;      ///< training samples "a:b"; empty: all
  std::string validate;   ///< validation samples "c:d" or another recording's CSV; empty: none
  EvalMode mode = EvalMode::simulation;
  std::string plot;           ///< PNG of measured vs model to write; empty: none
  ProgressCallback progress;  ///< grey-box fits' iterations; empty: none
  /// Grey-box fits: parameters held at a value (GreyboxOptions::held); InputError for another
  /// model kind.
  std::vector<std::pair<std::string, double>> held;
  /// Damper model: fit the inertance even where it removes under 10 % of the residual energy
  /// (GreyboxOptions::min_inertance_gain = 0).
  bool keep_inertance = false;
  /// Grey-box fits: [s] the motion drive read this much later (GreyboxOptions::motion_lead).
  double motion_lead = 0.0;
  /// Grey-box fits: leads tried besides, the one of best training FIT kept
  /// (fit_searching_motion_lead); empty: motion_lead as given.
  std::vector<double> motion_leads;
  /// Reads a recording (the CLI's reader also reports its warnings).
  std::function<lumped::Recording(const std::string&)> load_recording;
};

/// Where the validation data come from.
struct Validation {
  std::optional<lumped::SampleRange> range;  ///< part of the same recording
  std::optional<lumped::Recording> other;    ///< another recording of the same device
};

/// What one fit produced, whatever the model kind.
struct FitReport {
  std::string model;
  nlohmann::json fitted;  ///< the fitted-model document (identify/fit_model_json.hpp)
  nlohmann::json params = nlohmann::json::object();
  nlohmann::json standard_errors;  ///< grey-box only
  /// grey-box only: the parameters with units and standard errors (parameter_remark reads them)
  std::vector<FittedParameter> parameters;
  lumped::Metrics train;
  std::optional<lumped::Metrics> validation;
  std::vector<double> train_output, validation_output;
  std::optional<StabilityVerdict> train_stability;       ///< black-box, simulation mode only
  std::optional<StabilityVerdict> validation_stability;  ///< black-box, simulation mode only
  /// [s] grey-box: the leading rest over which the model's output is tared to the training /
  /// validation recording's level (GreyboxFit::tared_rest_seconds); 0 where it is not tared
  double tared_at_rest_s = 0.0, validation_tared_at_rest_s = 0.0;
  /// grey-box, tared training: the model's level in motion above its rest's, with the output's
  /// unit (level_in_motion_above_rest)
  std::optional<std::pair<double, std::string>> level_above_rest;
  /// grey-box and valve-chain: what of the validation part's drive lies beyond the training
  /// part's (identify/operating_range.hpp)
  std::vector<RangeExcess> validation_beyond;
};

/// A finished fit: the request, the data it used and the report.
struct FitRun {
  FitRequest request;
  lumped::Recording recording;
  lumped::SampleRange train;
  Validation validation;
  FitReport report;
  /// FIT% of the recording's own mean cycle on the training / validation samples (periodic
  /// drives only, identify/repeatability.hpp).
  std::optional<double> train_repeatability, validation_repeatability;
  /// How a recording too long was thinned ("REC.csv: every 50-th of its ... samples"), if any;
  /// the sample ranges above are then the thinned recording's.
  std::vector<std::string> thinning;
};

/// Reads the recording and validation data, fits the model, writes the plot if asked. InputError
/// for an unknown model, bad ranges, a validation recording of another kind or a missing gnuplot.
FitRun run_fit(const FitRequest& request);

/// The fitted model (readable by read_fit_model_json), then how well it fits (`fit --json`).
nlohmann::json fit_run_json(const FitRun& run);

/// The text report of `fit`: metrics per part, repeatability, parameters with standard errors.
void write_fit_run_text(const FitRun& run, std::ostream& out);

}  // namespace rheomag::identify
