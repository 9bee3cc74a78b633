// rheomag diagnose: name the physics a recording shows and its baseline model lacks. The method
// lives in diagnose/diagnose_*.hpp; this file reads the recording, runs it and prints the result.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "app/command.hpp"
#include "app/progress_lines.hpp"
#include "core/error.hpp"
#include "diagnose/diagnose_report.hpp"
#include "diagnose/diagnose_run.hpp"
#include "identify/fit_model_json.hpp"
#include "lumped/metrics.hpp"
#include "lumped/recording_excerpt.hpp"
#include "lumped/recording_io.hpp"

namespace {

using namespace rheomag;

struct DiagnoseCliOptions {
  std::string recording;
  std::string meta;
  std::string out;
  std::string samples;
  std::string baseline;
  std::string reference;
  bool json = false;
  bool quiet = false;
};

/// The recording, with its sidecar from --meta when given.
lumped::Recording read_input(const DiagnoseCliOptions& o) {
  if (o.meta.empty()) return rheomag::app::load_recording(o.recording);
  auto rec = lumped::read_csv_samples(o.recording);
  rec.meta = lumped::read_sidecar(o.meta);
  auto need = rec.meta.drive;
  need.push_back(rec.meta.output);
  for (const auto& c : need)
    if (!rec.columns.count(c))
      throw InputError(o.recording + ": column '" + c + "' named in " + o.meta +
                       " is not in the CSV");
  return rec;
}

/// The example sidecar the repository ships for a recording of this name
/// (tests/data/diagnosis/STEM.toml, docs/diagnosis.md), as a path from the working directory;
/// empty when there is none (an installed rheomag without its source tree).
std::string shipped_sidecar(const std::string& recording) {
  namespace fs = std::filesystem;
  const fs::path example = fs::path(RHEOMAG_SOURCE_DIR) / "tests" / "data" / "diagnosis" /
                           fs::path(recording).filename().replace_extension(".toml");
  std::error_code ec;
  if (!fs::is_regular_file(example, ec)) return {};
  const fs::path relative = fs::relative(example, fs::current_path(), ec);
  return (ec || relative.empty() || relative.native().rfind("../..", 0) == 0 ? example : relative)
      .string();
}

/// An error about the sidecar (missing, or lacking what the baseline needs: the drive, the rig)
/// completed with the options that fix it: --meta with a sidecar that describes the recording
/// (the shipped example when there is one) or --baseline with a fitted model.
[[noreturn]] void rethrow_with_fix(const InputError& e, const DiagnoseCliOptions& o) {
  const std::string what = e.what();
  const std::string sidecar = o.meta.empty() ? lumped::sidecar_path_for(o.recording) : o.meta;
  // A bad value ("rec.toml:6: ...") names its line and is fixed there, not by another file.
  if (!o.baseline.empty() || what.rfind(sidecar + ": ", 0) != 0) throw e;
  const std::string example = shipped_sidecar(o.recording);
  throw InputError(
      what +
      "\n  fix: give a sidecar that describes the recording's rig and drive with --meta FILE" +
      (example.empty() ? std::string(" (docs/diagnosis.md, \"Sidecar\")")
                       : " (one ships for this recording: --meta " + example + ")") +
      ", or a fitted model as the baseline with --baseline MODEL.json (from "
      "'rheomag fit " +
      o.recording + " --model M --json > MODEL.json')");
}

/// Reads the recording, diagnoses it and prints or writes the result.
void run(const DiagnoseCliOptions& o) {
  auto rec = read_input(o);
  if (!o.samples.empty())
    rec = lumped::excerpt(rec, lumped::parse_sample_range(o.samples, rec.t.size(), "--samples"));
  diagnose::DiagnoseOptions options;
  if (!o.baseline.empty())
    options.baseline_model =
        diagnose::ModelBaseline{identify::read_fit_model_json(o.baseline), o.baseline};
  if (!o.reference.empty()) options.reference = rheomag::app::load_recording(o.reference);
  if (!o.quiet) options.progress = rheomag::app::progress_lines("diagnose", std::cerr);
  const auto d = diagnose::diagnose(rec, options);
  if (!o.out.empty()) diagnose::write_diagnosis_outputs(d, o.out);
  if (o.json)
    rheomag::app::print_json(diagnose::diagnosis_json(d), 2);
  else
    std::cout << diagnose::diagnosis_text(d);
}

const bool diagnose_registered = app::register_command([](CLI::App& root) {
  auto o = std::make_shared<DiagnoseCliOptions>();
  CLI::App* cmd = root.add_subcommand(
      "diagnose",
      "Find the physics a recording shows and its baseline model leaves out.\n"
      "1. Baseline from everything the sidecar states (rig, coil resistance and inductance,\n"
      "   chambers, the valve's static map as a table or the FE chain of its [valve] case); its\n"
      "   static parameters (yield scale, viscous resistance or scale, force offset) and the\n"
      "   recording's nuisances (output delay up to +-2 samples, pre-yield smoothness, a\n"
      "   table map's knee between its Bingham line and the exact slit law) are calibrated by\n"
      "   least squares first.\n"
      "2. The residual is located in time windows tagged by regime (flow reversal, current edge,\n"
      "   steady, drift, high frequency) and correlated with the inputs.\n"
      "3. Candidates (compressibility, fluid_inertia, magnetic_hysteresis, eddy_currents,\n"
      "   mr_response_time, coil_inductance, coil_heating, friction, pre_yield,\n"
      "   fluid_heating) are fitted on top; one is accepted only if it lowers BIC by > 10,\n"
      "   removes >= 10 % of the residual energy above the noise floor, has a time constant\n"
      "   above one sample and a size parameter known to 50 %, has parameters its candidate\n"
      "   finds plausible (also after the joint re-fit), and cuts the error on held-out time\n"
      "   blocks by > 3 %;\n"
      "   forward selection, then a joint re-fit (the output delay held at 0 there unless it\n"
      "   lowers BIC by more than 2). Candidates that explain the data equally are reported\n"
      "   together; each size linear in its effect (mass, friction, spring) comes with its trade\n"
      "   per ms of output delay and the effects of its shape on the drive ('size:' lines,\n"
      "   JSON size_sensitivity): what one recording cannot tell it from.\n"
      "Exit 2 for bad input (recording format, missing sidecar keys, a [valve] case that does not\n"
      "exist or solve, a --baseline model of another rig or other columns, recording too\n"
      "short/flat).");
  cmd->add_option("recording", o->recording, "Recording CSV (fixed format; sidecar beside it)")
      ->required();
  cmd->add_option("--meta", o->meta, "Sidecar TOML to use instead of the one beside the CSV")
      ->check(rheomag::app::non_empty());
  cmd->add_option("--baseline", o->baseline,
                  "Fitted-model JSON ('rheomag fit --json' or 'fit-family --json', grey-box or "
                  "valve-chain) to use as the baseline instead of the sidecar's rig: its output "
                  "is the baseline, its parameters are held, its output scale and offset "
                  "calibrated; candidates act on its inputs and output")
      ->check(rheomag::app::non_empty());
  cmd->add_option("--reference", o->reference,
                  "A recording of the same device from before (its sidecar beside it), diagnosed "
                  "against the same --baseline model: the report adds each effect's change from "
                  "it (friction, fluid_inertia, gas_spring: both recordings fitted with what "
                  "either named and these three, today's output delay held at the reference's; "
                  "today's size minus the reference's, so what the model already missed on this "
                  "device is not counted as a change; effects the drive cannot tell apart, a "
                  "mass and a spring on one sinusoid, also given together)")
      ->check(rheomag::app::non_empty());
  cmd->add_option("--out", o->out, "Folder for diagnosis.json, report.html and traces.csv")
      ->check(rheomag::app::non_empty());
  cmd->add_option("--samples", o->samples,
                  "Diagnose only samples a:b (half-open indices; 'a:' to the end), e.g. an excerpt "
                  "of a long recording")
      ->check(rheomag::app::non_empty());
  cmd->add_flag("--json", o->json, "Print the diagnosis as one JSON object on stdout");
  cmd->add_flag("--quiet", o->quiet,
                "Do not report progress (each stage and candidate fit with its time) on stderr");
  cmd->callback([o]() {
    try {
      run(*o);
    } catch (const InputError& e) {
      rethrow_with_fix(e, *o);
    }
  });
});

}  // namespace
