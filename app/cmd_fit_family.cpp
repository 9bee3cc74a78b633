// rheomag fit-family: one grey-box model with current-dependent parameters fitted jointly on
// several recordings of a device (e.g. all currents at two frequencies), then used to predict
// other recordings; per-recording FIT%, RMSE% and RE (paper 001 eq. 10). The method lives in
// identify/current_dependent_fit.hpp, its JSON and text in identify/family_fit_output.hpp; this
// file maps options to them and prints the result.

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/progress_lines.hpp"
#include "core/error.hpp"
#include "identify/current_dependent_fit.hpp"
#include "identify/family_fit_output.hpp"
#include "identify/family_report.hpp"
#include "identify/motion_lead_search.hpp"
#include "lumped/recording_io.hpp"

namespace {

using namespace rheomag::lumped;
using namespace rheomag::identify;

struct FamilyOptions {
  std::vector<std::string> recordings;
  std::vector<std::string> predict;
  std::string model;
  int decimation = 4;
  int starts = 2;
  int threads = 0;
  int refit_iterations = 30;
  double max_substep = 2e-3;
  bool json = false;
  bool quiet = false;
  bool cross_validate = false;
  std::string report;
  std::string viscosity_nuisance;    ///< "LO:HI" or empty
  std::vector<std::string> holds;    ///< --hold NAME=VALUE
  bool keep_inertance = false;       ///< --keep-inertance
  std::string motion_lead = "auto";  ///< --motion-lead: "auto" or [s]
};

/// The --viscosity-nuisance bounds "LO:HI" (0 < LO <= 1 <= HI <= 100).
ViscosityNuisance parse_viscosity_nuisance(const std::string& text) {
  ViscosityNuisance n;
  const auto colon = text.find(':');
  std::size_t used_lo = 0, used_hi = 0;
  try {
    if (colon == std::string::npos) throw std::invalid_argument(text);
    n.lower = std::stod(text.substr(0, colon), &used_lo);
    n.upper = std::stod(text.substr(colon + 1), &used_hi);
  } catch (const std::exception&) {
    used_lo = 0;
  }
  if (used_lo == 0 || used_lo != colon || used_hi != text.size() - colon - 1 || !(n.lower > 0.0) ||
      !(n.lower <= 1.0) || !(n.upper >= 1.0) || !(n.upper <= 100.0))
    throw rheomag::InputError(
        "--viscosity-nuisance: expected LO:HI with 0 < LO <= 1 <= HI <= 100 (bounds of each "
        "recording's viscosity factor, e.g. 0.5:2), got \"" +
        text + "\"");
  return n;
}

std::string model_list() {
  std::string names;
  for (const std::string& n : greybox_model_names()) names += (names.empty() ? "" : " | ") + n;
  return names;
}

void run_fit_family(const FamilyOptions& o) {
  if (!is_greybox_model(o.model))
    throw rheomag::InputError("--model: '" + o.model + "' is not a grey-box model (" +
                              model_list() + ")");
  std::vector<Recording> training, prediction;
  for (const auto& f : o.recordings) {
    training.push_back(rheomag::app::load_recording(f));
    training.back().require_varying(training.back().meta.output);
  }
  for (const auto& f : o.predict) prediction.push_back(rheomag::app::load_recording(f));
  FamilyFitOptions options;
  options.greybox.held = rheomag::app::parse_holds(o.holds);
  if (o.keep_inertance) options.greybox.min_inertance_gain = 0.0;
  options.decimation = o.decimation;
  if (o.motion_lead == "auto")
    options.motion_leads = default_motion_leads();
  else
    options.greybox.motion_lead = std::stod(o.motion_lead);  // checked by add_motion_lead_option
  options.greybox.starts = o.starts;
  options.greybox.max_substep = o.max_substep;
  options.greybox.threads = o.threads;
  options.cross_validate = o.cross_validate;
  options.refit_iterations = o.refit_iterations;
  if (!o.viscosity_nuisance.empty())
    options.viscosity_nuisance = parse_viscosity_nuisance(o.viscosity_nuisance);
  if (!o.quiet) options.greybox.progress = rheomag::app::progress_lines("fit-family", std::cerr);
  const FamilyFit r = fit_current_dependent(training, o.model, prediction, options);
  if (!o.report.empty()) write_family_report(o.report, r, training, prediction);
  if (o.json)
    rheomag::app::print_json(
        family_fit_json(r, training.front().meta, o.decimation, o.cross_validate));
  else
    write_family_fit_text(r, training.size(), o.decimation, std::cout);
}

const bool fit_family_registered = rheomag::app::register_command([](CLI::App& root) {
  auto o = std::make_shared<FamilyOptions>();
  CLI::App* cmd = root.add_subcommand(
      "fit-family",
      "Fit one grey-box model jointly on several recordings of the same device (e.g. every\n"
      "current at several strokes and frequencies), one parameter set whose field terms are\n"
      "smooth in the current, each recording simulated from rest and weighted by its own\n"
      "spread; predict other recordings; reports FIT% and RE (paper 001 eq. 10) per recording.");
  cmd->add_option("recordings", o->recordings, "Training recordings (CSV with .toml sidecars)")
      ->required();
  cmd->add_option("--model", o->model, model_list())->required();
  cmd->add_option("--predict", o->predict, "Recordings to predict with the fitted model")
      ->check(rheomag::app::non_empty());
  cmd->add_option("--decimation", o->decimation,
                  "Fit on every n-th sample of each training recording (samples 0, n, 2n, ...; "
                  "the FIT of each recording is still computed on every sample)")
      ->capture_default_str()
      ->check(rheomag::app::in_domain(rheomag::Domain::between(1, 100).whole()));
  cmd->add_option("--starts", o->starts, "Multi-start count of the fit")
      ->capture_default_str()
      ->check(rheomag::app::in_domain(rheomag::Domain::between(1, 16).whole()));
  cmd->add_option(
         "--threads", o->threads,
         "Threads of the fit's starts and of the --cross-validate refits, which run "
         "beside the main fit when it is not 1 (0: one per core); the result does not "
         "depend on it while it is at most --starts, beyond rounding (about 1e-12 relative)")
      ->capture_default_str()
      ->check(rheomag::app::in_domain(rheomag::Domain::between(0, 256).whole()));
  cmd->add_option("--max-substep", o->max_substep,
                  "[s] longest RK4 substep inside the fit (stiff states shorten it further)")
      ->capture_default_str()
      ->check(rheomag::app::in_domain(rheomag::Domain::between(1e-6, 1.0, "s")));
  cmd->add_option("--report", o->report,
                  "Write DIR/report.html: measured vs model loops of every recording, parameters "
                  "with standard errors and their field dependence, FIT per recording")
      ->check(rheomag::app::non_empty());
  cmd->add_flag("--json", o->json,
                "Print one JSON object: the fitted model (readable back as a model file, "
                "docs/fit-model-json.md), params, train and prediction (arrays of {file, "
                "field, fit_percent, rmse_percent, re, mean_removed, tared_at_rest_s, band_rms, "
                "band_percent, "
                "repeatability_percent, level_fit_percent, level_pure_fit_percent, level_gain, "
                "level_offset, level_window_s, level_window_start_s, viscosity_factor, "
                "viscosity_temperature_offset_k, regimes: the residual's share in the reversals "
                "and in the settled strokes of each direction, {transition, positive, negative} "
                "each {time_percent, energy_percent, rms, mean}, beyond_training: what of a "
                "predicted recording's drive lies beyond the training recordings' "
                "(operating_range: their field levels, peak speeds and strokes), each {quantity, "
                "column, unit, value, trained_low, trained_high, text}}), "
                "held_out (the same, with --cross-validate; beyond_training: beyond the other "
                "training recordings', those its refit was fitted on), mode");
  rheomag::app::add_hold_option(cmd, o->holds);
  rheomag::app::add_keep_inertance_flag(cmd, o->keep_inertance);
  rheomag::app::add_motion_lead_option(
      cmd, o->motion_lead,
      "whose training recordings, simulated at full rate, have the lowest sum of (1 - FIT)^2; with "
      "--cross-validate each half searches its own and a refit takes the lead of the half it "
      "starts from");
  cmd->add_flag("--cross-validate", o->cross_validate,
                "Also refit once without each training recording and predict it (leave one "
                "recording out): the FIT to expect on a test the fit has not seen. Costs a fit of "
                "each half of the recordings and one short refit per training recording, run "
                "side by side (--threads); JSON key held_out, a report column. A left-out "
                "test whose field, peak speed or stroke lies beyond the others' is named as an "
                "extrapolation, and the held-out FIT of the tests inside is given apart");
  cmd->add_option("--refit-iterations", o->refit_iterations,
                  "--cross-validate: the most iterations of each refit, started from the fit of "
                  "the half of the recordings that does not hold the left-out one (30: the utfsm "
                  "refits converge, 60 give the same held-out FITs); 0: every refit from the "
                  "nominal start with --starts (the slower cold refits)")
      ->capture_default_str()
      ->check(rheomag::app::in_domain(rheomag::Domain::between(0, 1000).whole()));
  cmd->add_option("--viscosity-nuisance", o->viscosity_nuisance,
                  "LO:HI: let each training recording's viscosity factor float within [LO, HI] "
                  "(e.g. 0.5:2), a fitted nuisance for a fluid temperature that was not recorded: "
                  "the viscous terms of that recording are scaled by it, alternately with the "
                  "joint fit (two rounds); reported per recording with the temperature it stands "
                  "for at 2 %/K (JSON viscosity_factor, viscosity_temperature_offset_k). Predicted "
                  "recordings are run at factor 1 (docs/thermal.md)")
      ->check(rheomag::app::non_empty());
  cmd->add_flag("--quiet", o->quiet, "No progress lines on stderr");
  cmd->callback([o]() { run_fit_family(*o); });
});

}  // namespace
