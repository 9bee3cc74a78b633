// rheomag simulate: run a lumped model spec (virtual rig) and write a recording (CSV + sidecar).

#include <CLI/CLI.hpp>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "app/command.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "coupling/simulation_spec.hpp"
#include "identify/fit_model_json.hpp"
#include "lumped/recording_io.hpp"
#include "lumped/signals.hpp"

namespace {

struct SimulateOptions {
  std::string spec, input, out;
  std::vector<std::string> signals;
  double duration = 10.0, rate = 1000.0;
  bool json = false;
};

void print_written(const SimulateOptions& o, const rheomag::lumped::Recording& rec);

/// A model fitted by `fit` / `fit-family --json` run on a recording's drive columns: the recording
/// with its output replaced by the model's.
rheomag::lumped::Recording simulate_fitted_model(const SimulateOptions& o) {
  using namespace rheomag::lumped;
  using namespace rheomag::identify;
  using namespace rheomag::coupling;
  if (o.input.empty() || !o.signals.empty())
    throw rheomag::InputError(o.spec +
                              ": a fitted model runs on a recording's drive columns: give --input "
                              "REC.csv (with its sidecar), not --signal");
  const FitModel model = read_fit_model_json(o.spec);
  Recording rec = rheomag::app::load_recording(o.input);
  rec.columns[rec.meta.output] = simulate_fit_model(rec, model);
  rec.meta.description =
      "simulated by the fitted " + model.model + " model " + o.spec + " on the drive of " + o.input;
  return rec;
}

/// True if `path` names a fitted model: a .json file (any case), or a JSON object under any
/// other name (`fit --json > model.out`: its first character after white space and a byte-order
/// mark is '{', which no TOML document starts with).
bool is_fitted_model_file(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".json") return true;
  rheomag::require_regular_input_file(path, "spec or model file");
  std::ifstream in(path, std::ios::binary);
  char c = 0;
  while (in.get(c))
    if (!std::isspace(static_cast<unsigned char>(c)) && c != '\xEF' && c != '\xBB' && c != '\xBF')
      return c == '{';
  return false;
}

void run_simulate(const SimulateOptions& o) {
  using namespace rheomag::lumped;
  using namespace rheomag::identify;
  using namespace rheomag::coupling;
  if (is_fitted_model_file(o.spec)) {
    const Recording rec = simulate_fitted_model(o);
    write_recording(rec, o.out);
    print_written(o, rec);
    return;
  }
  const SimulationSpec spec = read_simulation_spec(o.spec);
  Recording drive;
  if (!o.input.empty()) {
    if (!o.signals.empty()) throw rheomag::InputError("give either --input or --signal, not both");
    drive = read_csv_samples(o.input);
  } else {
    if (o.signals.empty())
      throw rheomag::InputError("give --input REC.csv or at least one --signal");
    drive.t = uniform_times(o.duration, o.rate);
    for (const auto& s : o.signals) add_signal(drive, s);
  }
  Recording rec = simulate_spec(spec, drive);
  write_recording(rec, o.out);
  print_written(o, rec);
}

/// What was written: one JSON object (--json) or a line.
void print_written(const SimulateOptions& o, const rheomag::lumped::Recording& rec) {
  using rheomag::lumped::sidecar_path_for;
  if (o.json) {
    std::cout << "{\"out\": \"" << o.out << "\", \"sidecar\": \"" << sidecar_path_for(o.out)
              << "\", \"samples\": " << rec.t.size() << ", \"output\": \"" << rec.meta.output
              << "\", \"drive\": [";
    for (std::size_t k = 0; k < rec.meta.drive.size(); ++k)
      std::cout << (k ? ", " : "") << "\"" << rec.meta.drive[k] << "\"";
    std::cout << "]}\n";
  } else {
    std::cout << "wrote " << o.out << " and " << sidecar_path_for(o.out) << " (" << rec.t.size()
              << " samples, output " << rec.meta.output << ")\n";
  }
}

bool simulate_registered = rheomag::app::register_command([](CLI::App& root) {
  auto opts = std::make_shared<SimulateOptions>();
  CLI::App* cmd = root.add_subcommand(
      "simulate",
      "Simulate a lumped model spec (a virtual rig: cases/rigs/*.toml, format in "
      "docs/dynamics.md)\n"
      "driven by a recording's columns or by generated signals, and write a recording (CSV +\n"
      "TOML sidecar) in the fixed format, ready for 'rheomag fit' or 'rheomag diagnose'.\n"
      "Example: rheomag simulate cases/rigs/bypass_cylinder.toml \\\n"
      "  --signal displacement=sine:amplitude=0.025,frequency=0.75 \\\n"
      "  --signal current=steps:levels=0/0.5/1,period=2 --duration 6 --rate 1000 --out sim.csv\n"
      "A fitted model (fit / fit-family --json > model.json) runs on a recording's drive:\n"
      "  rheomag simulate model.json --input today.csv --out predicted.csv");
  cmd->add_option("spec", opts->spec,
                  "model spec (TOML), or a fitted model (JSON written by fit / fit-family --json: "
                  "run on --input's drive, its output replaced by the model's)")
      ->required();
  cmd->add_option("--input", opts->input, "recording CSV whose columns drive the model")
      ->check(rheomag::app::non_empty());
  cmd->add_option("--signal", opts->signals,
                  "generated drive COLUMN=KIND:key=value,... (repeatable). Kinds: "
                  "sine:amplitude,frequency[,offset] (displacement sine also writes velocity); "
                  "constant:value; steps:levels=a/b/c,period; square:low,high,period");
  cmd->add_option("--duration", opts->duration, "length of generated signals [s]")
      ->capture_default_str();
  cmd->add_option("--rate", opts->rate, "sample rate of generated signals [Hz]")
      ->capture_default_str();
  cmd->add_option("--out", opts->out, "output recording CSV (sidecar .toml written beside it)")
      ->required();
  cmd->add_flag("--json", opts->json, "print one JSON object describing the output");
  cmd->callback([opts]() { run_simulate(*opts); });
});

}  // namespace
