// rheomag fit-family: one grey-box model with current-dependent parameters fitted jointly on
// several recordings of a device (e.g. all currents at two frequencies), then used to predict
// other recordings; per-recording FIT%, RMSE% and RE (paper 001 eq. 10). The method lives in
// lumped/current_dependent_fit.hpp; this file maps options to it and prints the result.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/progress_lines.hpp"
#include "core/error.hpp"
#include "lumped/current_dependent_fit.hpp"
#include "lumped/family_report.hpp"
#include "lumped/fit_model_json.hpp"
#include "lumped/recording_io.hpp"

namespace {

using namespace rheomag::lumped;

struct FamilyOptions {
  std::vector<std::string> recordings;
  std::vector<std::string> predict;
  std::string model;
  int decimation = 4;
  int starts = 2;
  double max_substep = 2e-3;
  bool json = false;
  bool quiet = false;
  bool cross_validate = false;
  std::string report;
};

std::string model_list() {
  std::string names;
  for (const std::string& n : greybox_model_names()) names += (names.empty() ? "" : " | ") + n;
  return names;
}

nlohmann::json member_json(const FamilyMember& m) {
  return {{"file", m.csv_path},
          {"field", m.field},
          {"fit_percent", m.metrics.fit_percent},
          {"rmse_percent", m.metrics.rmse_percent},
          {"re", m.metrics.re},
          {"mean_removed", m.mean_removed},
          {"band_rms", m.band ? nlohmann::json(m.band->rms) : nlohmann::json()},
          {"band_percent", m.band ? nlohmann::json(m.band->percent) : nlohmann::json()},
          {"repeatability_percent",
           m.repeatability ? nlohmann::json(*m.repeatability) : nlohmann::json()}};
}

void print_members(const char* title, const std::vector<FamilyMember>& members) {
  const bool banded = std::any_of(members.begin(), members.end(),
                                  [](const FamilyMember& m) { return m.band.has_value(); });
  rheomag::app::print("%s\n  %-40s %8s %8s %8s %6s%s\n", title, "recording", "field", "FIT%", "RE",
                      "rep%", banded ? "  band% (1 sigma, parameters between recordings)" : "");
  for (const auto& m : members) {
    rheomag::app::print("  %-40s %8.3g %8.1f %8.3f", m.csv_path.c_str(), m.field,
                        m.metrics.fit_percent, m.metrics.re);
    if (m.repeatability)
      rheomag::app::print(" %6.1f", *m.repeatability);
    else
      rheomag::app::print(" %6s", "-");
    if (m.band) rheomag::app::print("  %5.1f", m.band->percent);
    rheomag::app::print(
        "%s\n", m.mean_removed ? "  (mean removed: compared without the model's mean)" : "");
  }
}

/// One line comparing the held-out FITs with the fitted ones: the median and the lowest of each.
void print_held_out_summary(const FamilyFit& r) {
  const auto fits = [](const std::vector<FamilyMember>& members) {
    std::vector<double> v;
    for (const auto& m : members) v.push_back(m.metrics.fit_percent);
    std::sort(v.begin(), v.end());
    return v;
  };
  const std::vector<double> held = fits(r.held_out), fitted = fits(r.training);
  const auto median = [](const std::vector<double>& v) {
    const std::size_t h = v.size() / 2;
    return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
  };
  rheomag::app::print(
      "held-out FIT: median %.1f %%, lowest %.1f %% (fitted on all: median %.1f %%, lowest "
      "%.1f %%)\n",
      median(held), held.front(), median(fitted), fitted.front());
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
  options.decimation = o.decimation;
  options.greybox.starts = o.starts;
  options.greybox.max_substep = o.max_substep;
  options.cross_validate = o.cross_validate;
  if (!o.quiet) options.greybox.progress = rheomag::app::progress_lines("fit-family", std::cerr);
  const FamilyFit r = fit_current_dependent(training, o.model, prediction, options);
  if (!o.report.empty()) write_family_report(o.report, r, training, prediction);
  if (!o.json) {
    rheomag::app::print("model %s, joint fit on %zu recordings (every %d-th sample)\n",
                        r.fit.model.c_str(), training.size(), o.decimation);
    rheomag::app::print("  %-24s %14s %-13s %-13s\n", "parameter", "value", "+- classical",
                        "+- between recordings");
    const auto error_column = [](const std::optional<double>& e) {
      if (e)
        rheomag::app::print(" +- %-10.3g", *e);
      else
        rheomag::app::print("    %-10s", "");
    };
    for (const auto& p : r.fit.params) {
      rheomag::app::print("  %-24s %14.6g", p.name.c_str(), p.value);
      error_column(p.standard_error);
      error_column(p.standard_error_between_recordings);
      rheomag::app::print(" %s%s\n", p.unit.c_str(),
                          p.fixed      ? " (fixed)"
                          : p.at_bound ? " (at bound)"
                                       : "");
    }
    print_members("training recordings:", r.training);
    if (!r.predicted.empty()) print_members("predicted recordings:", r.predicted);
    if (!r.held_out.empty()) {
      print_members("held out (each training recording predicted by the family fitted without it):",
                    r.held_out);
      print_held_out_summary(r);
    }
    rheomag::app::print(
        "rep%%: FIT of each recording's own mean cycle on its steady cycles, the most a model "
        "answering a periodic drive with a periodic output reaches there (- : drive not "
        "periodic)\n");
    return;
  }
  // The fitted model itself (readable by read_fit_model_json), then each recording's metrics.
  nlohmann::json j = fit_model_json(r.fit, training.front().meta);
  j["train"] = nlohmann::json::array();
  for (const auto& m : r.training) j["train"].push_back(member_json(m));
  j["prediction"] = nlohmann::json::array();
  for (const auto& m : r.predicted) j["prediction"].push_back(member_json(m));
  if (o.cross_validate) {
    j["held_out"] = nlohmann::json::array();
    for (const auto& m : r.held_out) j["held_out"].push_back(member_json(m));
  }
  j["decimation"] = o.decimation;
  j["mode"] = "simulation";
  rheomag::app::print_json(j);
}

const bool registered = rheomag::app::register_command([](CLI::App& root) {
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
                  "Keep every n-th sample of each training recording in the joint fit")
      ->check(CLI::Range(1, 100));
  cmd->add_option("--starts", o->starts, "Multi-start count of the fit")->check(CLI::Range(1, 16));
  cmd->add_option("--max-substep", o->max_substep,
                  "[s] longest RK4 substep inside the fit (stiff states shorten it further)")
      ->check(CLI::Range(1e-6, 1.0));
  cmd->add_option("--report", o->report,
                  "Write DIR/report.html: measured vs model loops of every recording, parameters "
                  "with standard errors and their field dependence, FIT per recording")
      ->check(rheomag::app::non_empty());
  cmd->add_flag("--json", o->json,
                "Print one JSON object: the fitted model (readable back as a model file, "
                "docs/fit-model-json.md), params, train and prediction (arrays of {file, "
                "field, fit_percent, rmse_percent, re, mean_removed, band_rms, band_percent, "
                "repeatability_percent}), "
                "held_out (the same, with --cross-validate), mode");
  cmd->add_flag("--cross-validate", o->cross_validate,
                "Also refit once without each training recording and predict it (leave one "
                "recording out): the FIT to expect on a test the fit has not seen. Costs one more "
                "fit per training recording; JSON key held_out, a report column");
  cmd->add_flag("--quiet", o->quiet, "No progress lines on stderr");
  cmd->callback([o]() { run_fit_family(*o); });
});

}  // namespace
