// rheomag simulate: run a lumped model spec (virtual rig) and write a recording (CSV + sidecar).

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "app/command.hpp"
#include "identify/simulate_run.hpp"
#include "lumped/recording_io.hpp"

namespace {

struct SimulateOptions {
  rheomag::identify::SimulateRequest request;
  std::string out;
  bool json = false;
};

void run_simulate(const SimulateOptions& o) {
  rheomag::identify::SimulateRequest request = o.request;
  request.load_recording = rheomag::app::load_recording;
  std::vector<rheomag::identify::RangeExcess> beyond;
  const rheomag::lumped::Recording rec = rheomag::identify::run_simulate(request, &beyond);
  rheomag::lumped::write_recording(rec, o.out);
  for (const auto& e : beyond)
    std::cerr << "note: " << o.request.input << " beyond the drive " << o.request.spec
              << " was fitted on: " << e.text() << "\n";
  if (o.json)
    rheomag::app::print_json(rheomag::identify::simulate_written_json(rec, o.out, beyond));
  else
    std::cout << "wrote " << o.out << " and " << rheomag::lumped::sidecar_path_for(o.out) << " ("
              << rec.t.size() << " samples, output " << rec.meta.output << ")\n";
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
      "  rheomag simulate model.json --input today.csv --out predicted.csv\n"
      "Where today's drive lies beyond the one the model was fitted on (its field levels, peak\n"
      "speeds, strokes: the model's operating_range), a note on stderr says so (JSON\n"
      "beyond_training): there the model extrapolates.");
  cmd->add_option("spec", opts->request.spec,
                  "model spec (TOML), or a fitted model (JSON written by fit / fit-family --json: "
                  "run on --input's drive, its output replaced by the model's)")
      ->required();
  cmd->add_option("--input", opts->request.input, "recording CSV whose columns drive the model")
      ->check(rheomag::app::non_empty());
  cmd->add_option("--signal", opts->request.signals,
                  "generated drive COLUMN=KIND:key=value,... (repeatable). Kinds: "
                  "sine:amplitude,frequency[,offset] (displacement sine also writes velocity); "
                  "constant:value; steps:levels=a/b/c,period; square:low,high,period");
  cmd->add_option("--duration", opts->request.duration, "length of generated signals [s]")
      ->capture_default_str();
  cmd->add_option("--rate", opts->request.rate, "sample rate of generated signals [Hz]")
      ->capture_default_str();
  cmd->add_option("--out", opts->out, "output recording CSV (sidecar .toml written beside it)")
      ->required();
  cmd->add_flag("--json", opts->json, "print one JSON object describing the output");
  cmd->callback([opts]() { run_simulate(*opts); });
});

}  // namespace
