#pragma once
// `rheomag simulate` as a library call: a lumped model spec (virtual rig) driven by a recording or
// generated signals, or a fitted model (fit / fit-family --json) run on a recording's drive;
// the simulated recording, and the JSON describing it once written. Shared by the CLI and the
// Python module.

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "identify/operating_range.hpp"
#include "lumped/recording.hpp"

namespace rheomag::identify {

/// What a simulation is asked for (the options of `rheomag simulate`; messages name them).
struct SimulateRequest {
  std::string spec;                  ///< model spec (TOML) or fitted model (JSON)
  std::string input;                 ///< recording CSV whose columns drive the model; or
  std::vector<std::string> signals;  ///< generated drives COLUMN=KIND:key=value,...
  double duration = 10.0;            ///< length of generated signals [s]
  double rate = 1000.0;              ///< sample rate of generated signals [Hz]
  /// Reads the recording of a fitted model's drive (the CLI's reader also reports warnings).
  std::function<lumped::Recording(const std::string&)> load_recording;
};

/// True if `path` names a fitted model: a .json file (any case), or a JSON object under any
/// other name (`fit --json > model.out`: its first character after white space and a byte-order
/// mark is '{', which no TOML document starts with).
bool is_fitted_model_file(const std::string& path);

/// The simulated recording. InputError for a bad spec, model or drive, or conflicting options.
/// For a fitted model that carries its training drive, `beyond` (if given) receives what of the
/// input's drive lies beyond it (the model extrapolates there); it is left empty otherwise.
lumped::Recording run_simulate(const SimulateRequest& request,
                               std::vector<RangeExcess>* beyond = nullptr);

/// The JSON of `rheomag simulate --json` once `rec` was written to `out`: out, sidecar,
/// samples, output, drive, and beyond_training (range_excess_json of `beyond`).
nlohmann::json simulate_written_json(const lumped::Recording& rec, const std::string& out,
                                     const std::vector<RangeExcess>& beyond = {});

}  // namespace rheomag::identify
