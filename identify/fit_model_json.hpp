#pragma once
// The fitted-model JSON that `rheomag fit --json` and `fit-family --json` print: self-contained
// (model, rig, drive and output columns, the settings the model was fitted with, parameters with
// units, the static map of a valve-chain model), so a model fitted once can be read back and run
// on another recording of the same device (e.g. as the baseline of a diagnosis).

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "identify/greybox.hpp"
#include "identify/operating_range.hpp"
#include "identify/valve_chain_fit.hpp"
#include "lumped/recording.hpp"

namespace rheomag::identify {

/// The value of the "format" key of a fitted-model JSON document.
inline constexpr std::string_view kFitModelFormat = "rheomag-fit-model/1";

/// A fitted model read back from its JSON: exactly one of `greybox`, `valve_chain` is set.
struct FitModel {
  std::string model;                         ///< "bingham", ..., "damper" or "valve-chain"
  std::optional<lumped::RigKind> rig;        ///< the fitted recording's [rig] kind, if it named one
  std::vector<std::string> drive;            ///< the fitted recording's drive columns
  std::string output;                        ///< the fitted recording's output column
  std::optional<GreyboxFit> greybox;         ///< setup and parameters (no simulated output)
  std::optional<ValveChainFit> valve_chain;  ///< setup with its static map, parameters
  /// The drive the model was fitted on (key "operating_range"; absent in files written before it).
  std::optional<OperatingRange> operating_range;
};

/// The JSON of a grey-box fit (fit or fit-family) of a recording with sidecar `meta`.
nlohmann::json fit_model_json(const GreyboxFit& fit, const lumped::RecordingMeta& meta);

/// The JSON of a valve-chain fit (its static map included) of a recording with sidecar `meta`.
nlohmann::json fit_model_json(const ValveChainFit& fit, const lumped::RecordingMeta& meta);

/// The JSON of a black-box fit (`name` as IdentModel::name(), its parameters): for people and
/// scripts; read_fit_model_json refuses it (the model's structure is not stored).
nlohmann::json black_box_model_json(const std::string& name,
                                    const std::vector<std::pair<std::string, double>>& params,
                                    const lumped::RecordingMeta& meta);

/// Reads a fitted-model document from `text`; `file` names it in messages. InputError
/// "file: key 'a.b': expected ..., got ..." on anything missing, mistyped or outside its domain.
FitModel parse_fit_model_json(std::string_view text, const std::string& file);

/// Reads the fitted-model JSON file `path` (see parse_fit_model_json).
FitModel read_fit_model_json(const std::filesystem::path& path);

/// The drive columns of a fitted model (field, motion, position; empty where it has none).
DriveColumns drive_columns(const GreyboxFit& fit);

/// The drive columns of a fitted valve-chain model (field and flow or motion, no position).
DriveColumns drive_columns(const ValveChainFit& fit);

/// What of `rec`'s drive lies beyond the range `model` was fitted on (beyond_range); empty when
/// within it or when the model carries no range.
std::vector<RangeExcess> beyond_fitted_range(const FitModel& model, const lumped::Recording& rec);

/// The model's free-run output on `rec` (same drive and output columns as the fitted recording;
/// InputError naming the file otherwise).
std::vector<double> simulate_fit_model(const lumped::Recording& rec, const FitModel& model);

}  // namespace rheomag::identify
