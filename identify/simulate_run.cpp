// `rheomag simulate` as a library call (see simulate_run.hpp).

#include "identify/simulate_run.hpp"

#include <cctype>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "coupling/simulation_spec.hpp"
#include "identify/fit_model_json.hpp"
#include "lumped/recording_io.hpp"
#include "lumped/signals.hpp"

namespace rheomag::identify {

namespace {

/// A fitted model run on a recording's drive columns: the recording with its output replaced
/// by the model's.
lumped::Recording simulate_fitted_model(const SimulateRequest& r,
                                        std::vector<RangeExcess>* beyond) {
  if (r.input.empty() || !r.signals.empty())
    throw InputError(r.spec +
                     ": a fitted model runs on a recording's drive columns: give --input "
                     "REC.csv (with its sidecar), not --signal");
  const FitModel model = read_fit_model_json(r.spec);
  lumped::Recording rec =
      r.load_recording ? r.load_recording(r.input) : lumped::read_recording(r.input);
  rec.columns[rec.meta.output] = simulate_fit_model(rec, model);
  if (beyond) *beyond = beyond_fitted_range(model, rec);
  rec.meta.description =
      "simulated by the fitted " + model.model + " model " + r.spec + " on the drive of " + r.input;
  return rec;
}

}  // namespace

bool is_fitted_model_file(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".json") return true;
  require_regular_input_file(path, "spec or model file");
  std::ifstream in(path, std::ios::binary);
  char c = 0;
  while (in.get(c))
    if (!std::isspace(static_cast<unsigned char>(c)) && c != '\xEF' && c != '\xBB' && c != '\xBF')
      return c == '{';
  return false;
}

lumped::Recording run_simulate(const SimulateRequest& r, std::vector<RangeExcess>* beyond) {
  if (beyond) beyond->clear();
  if (is_fitted_model_file(r.spec)) return simulate_fitted_model(r, beyond);
  const coupling::SimulationSpec spec = coupling::read_simulation_spec(r.spec);
  lumped::Recording drive;
  if (!r.input.empty()) {
    if (!r.signals.empty()) throw InputError("give either --input or --signal, not both");
    drive = lumped::read_csv_samples(r.input);
  } else {
    if (r.signals.empty()) throw InputError("give --input REC.csv or at least one --signal");
    drive.t = lumped::uniform_times(r.duration, r.rate);
    for (const auto& s : r.signals) lumped::add_signal(drive, s);
  }
  return coupling::simulate_spec(spec, drive);
}

nlohmann::json simulate_written_json(const lumped::Recording& rec, const std::string& out,
                                     const std::vector<RangeExcess>& beyond) {
  return {{"out", out},
          {"sidecar", lumped::sidecar_path_for(out)},
          {"samples", rec.t.size()},
          {"output", rec.meta.output},
          {"drive", rec.meta.drive},
          {"beyond_training", range_excess_json(beyond)}};
}

}  // namespace rheomag::identify
