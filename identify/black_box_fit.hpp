#pragma once
// Black-box identification entry point: model names ("arx:2,4,1", "tf:auto", "narx", "hw",
// "svr"...), fitting on training data, and running a fitted model on other data with the
// FIT% / RMSE% / RE metrics of lumped/metrics.hpp.

#include <memory>
#include <string>
#include <vector>

#include "identify/black_box_model.hpp"
#include "lumped/metrics.hpp"
#include "lumped/recording.hpp"

namespace rheomag::identify {

/// Black-box model families.
enum class BlackBoxFamily { arx, tf, narx, hw, svr };

/// A parsed black-box model name: family, optional numbers, "auto" flag and criterion.
struct ModelSpec {
  BlackBoxFamily family = BlackBoxFamily::arx;
  std::vector<int> numbers;  ///< the comma-separated orders after "family:"
  bool automatic = false;    ///< "arx:auto", "tf:auto"
  bool fpe = false;          ///< "arx:auto,fpe": FPE instead of AIC
  std::string text;          ///< as given
};

/// Every model name `rheomag fit` knows, black-box families first, then grey-box models.
const std::vector<std::string>& known_model_names();

/// The name in `names` closest to `given` (Levenshtein distance on the part before ':').
std::string closest_model_name(const std::string& given, const std::vector<std::string>& names);

/// True if `text` names a black-box family (arx, tf, narx, hw, svr), with or without orders.
bool is_black_box_model(const std::string& text);

/// Parses a black-box model name; InputError naming the option and the expected form.
ModelSpec parse_model_spec(const std::string& text);

/// Fits the model `spec` to `train`; InputError if the data are too short for its orders.
std::unique_ptr<IdentModel> fit_black_box(const ModelSpec& spec, const IoData& train);

/// Metrics of `model` on `data` in `mode`, skipping the model's warm-up samples; `output`
/// receives the model output (same length as data.y) if not null.
lumped::Metrics evaluate(const IdentModel& model, const IoData& data, EvalMode mode,
                         Eigen::VectorXd* output = nullptr);

/// Identification data from a recording: its sidecar's drive columns and output column.
/// InputError naming the file if sampling is not uniform (within 0.1 %).
IoData io_data_from_recording(const lumped::Recording& rec);

}  // namespace rheomag::identify
