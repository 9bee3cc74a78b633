// rheomag fit: identify a model of a recording (black-box or grey-box) and report FIT%, RMSE%
// and RE on the training and validation parts. The workflow lives in identify/fit_run.hpp (the
// methods in identify/); this file maps options to it and prints the result.

#include <CLI/CLI.hpp>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/progress_lines.hpp"
#include "identify/fit_run.hpp"
#include "identify/motion_lead_search.hpp"

namespace {

using namespace rheomag::identify;

/// The options of `rheomag fit`: the request plus how to print it.
struct FitOptions {
  FitRequest request;
  std::vector<std::string> holds;    ///< --hold NAME=VALUE
  bool keep_inertance = false;       ///< --keep-inertance
  std::string motion_lead = "auto";  ///< --motion-lead: "auto" or [s]
  bool json = false;
  bool quiet = false;
};

void run_fit_command(const FitOptions& o) {
  FitRequest request = o.request;
  request.load_recording = rheomag::app::load_recording;
  request.held = rheomag::app::parse_holds(o.holds);
  request.keep_inertance = o.keep_inertance;
  if (o.motion_lead == "auto")
    request.motion_leads = default_motion_leads();
  else
    request.motion_lead = std::stod(o.motion_lead);  // checked by add_motion_lead_option
  if (!o.quiet) request.progress = rheomag::app::progress_lines("fit", std::cerr);
  const FitRun run = run_fit(request);
  if (o.json)
    rheomag::app::print_json(fit_run_json(run));
  else
    write_fit_run_text(run, std::cout);
}

const bool fit_registered = rheomag::app::register_command([](CLI::App& root) {
  auto o = std::make_shared<FitOptions>();
  CLI::App* cmd = root.add_subcommand(
      "fit",
      "Identify a model of a recording (CSV + TOML sidecar; the sidecar's drive columns are the\n"
      "inputs, its output column the signal to explain) and report FIT% (MATLAB compare),\n"
      "RMSE% (paper 000 eq. 6) and RE (paper 001 eq. 10) on the training and validation parts.\n"
      "Models:\n"
      "  arx:na,nb,nk | arx:auto[,aic|,fpe]  linear ARX, least squares; auto = AIC/FPE order\n"
      "                                      search over na 1..5, nb 1..5, nk 0..3\n"
      "  tf:np,nz | tf:auto                  continuous transfer function (tfest-like: SRIV\n"
      "                                      start, Levenberg-Marquardt on simulation error)\n"
      "  narx[:na,nb,nk[,degree]]            polynomial NARX, terms by FROLS (default degree 3)\n"
      "  hw[:nb,nf,nk[,breakpoints]]         Hammerstein-Wiener, piecewise-linear in/out maps\n"
      "  svr[:na,nb,nk]                      libsvm epsilon-SVR NARX with (C, gamma, eps) search\n"
      "  bingham | lugre | bouc-wen | maxwell | dahl | bi-viscous | tanh   grey-box models\n"
      "  damper                              physically based damper: valve map (Herschel-\n"
      "                                      Bulkley, pre-yield creep), compliance, seal\n"
      "                                      friction, fluid inertia, gas spring, field lag\n"
      "  valve-chain                         the sidecar's [valve] case through the fluid chain,\n"
      "                                      fitted yield/viscous scales, field lag, compliance\n"
      "tf and hw are output-error models: their prediction equals their simulation.\n"
      "Black-box models are checked in simulation mode (poles of the output recursion, bounded\n"
      "free run); an unstable one is reported as such instead of a FIT.");
  cmd->add_option("recording", o->request.recording, "Recording CSV (its .toml sidecar beside it)")
      ->required();
  cmd->add_option("--model", o->request.model,
                  "Model name: one of the list under 'Models:' in this help")
      ->required();
  cmd->add_option("--train", o->request.train,
                  "Training samples a:b, half-open sample indices [a, b) ('a:' to the end); "
                  "default all")
      ->check(rheomag::app::non_empty());
  cmd->add_option("--validate", o->request.validate,
                  "Validation samples c:d (half-open, must not overlap --train) or another "
                  "recording CSV of the same device")
      ->check(rheomag::app::non_empty());
  cmd->add_option("--mode", o->request.mode,
                  "simulation (free run, default) or prediction (one step ahead)")
      ->transform(CLI::CheckedTransformer(
                      std::map<std::string, EvalMode>{{"simulation", EvalMode::simulation},
                                                      {"prediction", EvalMode::prediction}},
                      CLI::ignore_case)
                      .description(""))
      ->type_name("simulation|prediction");
  rheomag::app::add_hold_option(cmd, o->holds);
  rheomag::app::add_keep_inertance_flag(cmd, o->keep_inertance);
  rheomag::app::add_motion_lead_option(
      cmd, o->motion_lead,
      "with the best FIT on the training samples (grey-box models; others take 0)");
  cmd->add_flag("--quiet", o->quiet, "No progress lines on stderr (grey-box fits report them)");
  cmd->add_flag("--json", o->json,
                "Print one JSON object: the fitted model (format, kind, model, rig, drive, output, "
                "setup, parameters with units, static_map of valve-chain, operating_range: the "
                "training part's field levels, peak speed and stroke; readable back as a "
                "model file, docs/fit-model-json.md), params, train and validation "
                "({fit_percent, rmse_percent, re, repeatability_percent, tared_at_rest_s: the "
                "leading rest the model's output is tared over, null if none; validation also "
                "beyond_training: what of its drive lies beyond the training part's}), mode");
  cmd->add_option("--plot", o->request.plot,
                  "Write a PNG figure (measured vs model, residual) with gnuplot")
      ->check(rheomag::app::output_file());
  cmd->callback([o]() { run_fit_command(*o); });
});

}  // namespace
