// The fit workflow of `rheomag fit`: reading the data, fitting the model, the plot, the JSON
// document and the text report.

#include "identify/fit_run.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <span>

#include "core/error.hpp"
#include "core/format_text.hpp"
#include "identify/black_box_fit.hpp"
#include "identify/fit_model_json.hpp"
#include "identify/fit_plot.hpp"
#include "identify/greybox.hpp"
#include "identify/motion_lead_search.hpp"
#include "identify/repeatability.hpp"
#include "identify/valve_chain_fit.hpp"
#include "lumped/motion_glitches.hpp"
#include "lumped/recording_excerpt.hpp"

namespace rheomag::identify {

using lumped::Metrics;
using lumped::Recording;
using lumped::SampleRange;

namespace {

bool looks_like_file(const std::string& text) {
  return text.find(':') == std::string::npos || std::filesystem::exists(text) ||
         (text.size() > 4 && text.compare(text.size() - 4, 4, ".csv") == 0);
}

std::string range_text(const SampleRange& r) {
  return std::to_string(r.begin) + ":" + std::to_string(r.end);
}

Validation read_validation(const FitRequest& o, const Recording& rec, const SampleRange& train) {
  Validation v;
  if (o.validate.empty()) return v;
  if (looks_like_file(o.validate)) {
    v.other = o.load_recording(o.validate);
    if (v.other->meta.drive != rec.meta.drive || v.other->meta.output != rec.meta.output)
      throw InputError("--validate " + o.validate +
                       ": its sidecar's drive/output columns differ from " + rec.meta.sidecar_path);
    return v;
  }
  v.range = lumped::parse_sample_range(o.validate, rec.t.size(), "--validate");
  if (v.range->begin < train.end && train.begin < v.range->end)
    throw InputError("--train " + range_text(train) + " and --validate " + range_text(*v.range) +
                     " overlap; validation samples must be unseen");
  return v;
}

Metrics metrics_on(const std::vector<double>& y, const std::vector<double>& yhat, SampleRange r) {
  return compute_metrics(std::span<const double>(y), std::span<const double>(yhat), r);
}

std::vector<double> to_std(const Eigen::VectorXd& v) {
  return {v.data(), v.data() + v.size()};
}

FitReport fit_black_box_model(const FitRequest& o, const Recording& rec, const SampleRange& train,
                              const Validation& val) {
  const ModelSpec spec = parse_model_spec(o.model);
  const IoData all = io_data_from_recording(rec);
  const IoData train_data =
      slice(all, static_cast<std::ptrdiff_t>(train.begin), static_cast<std::ptrdiff_t>(train.end));
  const std::unique_ptr<IdentModel> model = fit_black_box(spec, train_data);
  FitReport report;
  report.model = model->name();
  for (const auto& [name, value] : model->params()) report.params[name] = value;
  report.fitted = black_box_model_json(model->name(), model->params(), rec.meta);
  Eigen::VectorXd out;
  report.train = evaluate(*model, train_data, o.mode, &out);
  report.train_output = to_std(out);
  if (o.mode == EvalMode::simulation)
    report.train_stability = check_simulation_stability(*model, train_data);
  std::optional<IoData> val_data;
  if (val.range)
    val_data = slice(all, static_cast<std::ptrdiff_t>(val.range->begin),
                     static_cast<std::ptrdiff_t>(val.range->end));
  else if (val.other)
    val_data = io_data_from_recording(*val.other);
  if (val_data) {
    report.validation = evaluate(*model, *val_data, o.mode, &out);
    report.validation_output = to_std(out);
    if (o.mode == EvalMode::simulation)
      report.validation_stability = check_simulation_stability(*model, *val_data);
  }
  return report;
}

/// Report of a grey-box fit (GreyboxFit or ValveChainFit): parameters with standard errors (held
/// ones left out), its free run on the training and validation parts; `simulate_other` runs the
/// fitted model on a validation recording.
template <class Fit>
FitReport grey_box_report(
    const Fit& fit, const Recording& rec, const SampleRange& train, const Validation& val,
    const std::function<std::vector<double>(const Recording&)>& simulate_other) {
  FitReport report;
  report.model = fit.model;
  report.standard_errors = nlohmann::json::object();
  for (const auto& p : fit.params) {
    if (p.fixed && fit.model == "valve-chain") continue;  // no compliance: the drive is Q itself
    report.parameters.push_back(p);
    report.params[p.name] = p.value;
    report.standard_errors[p.name] = p.standard_error && std::isfinite(*p.standard_error)
                                         ? nlohmann::json(*p.standard_error)
                                         : nlohmann::json(nullptr);
  }
  report.train = fit.train;
  report.train_output.assign(fit.simulated.begin() + static_cast<std::ptrdiff_t>(train.begin),
                             fit.simulated.begin() + static_cast<std::ptrdiff_t>(train.end));
  const std::vector<double>& y = rec.column(rec.meta.output);
  if (val.range) {
    report.validation = metrics_on(y, fit.simulated, *val.range);
    report.validation_output.assign(
        fit.simulated.begin() + static_cast<std::ptrdiff_t>(val.range->begin),
        fit.simulated.begin() + static_cast<std::ptrdiff_t>(val.range->end));
  } else if (val.other) {
    report.validation_output = simulate_other(*val.other);
    const std::vector<double>& yv = val.other->column(val.other->meta.output);
    report.validation = metrics_on(yv, report.validation_output, SampleRange{0, yv.size()});
  }
  return report;
}

void reject_prediction_mode(const FitRequest& o) {
  if (o.mode == EvalMode::prediction)
    throw InputError("--mode prediction: grey-box model '" + o.model +
                     "' is a state-space model run in free simulation only");
}

/// Writes the training part's drive into the fitted model and notes what of the validation
/// part's drive lies beyond it.
void put_operating_range(FitReport& report, const DriveColumns& cols, const Recording& rec,
                         const SampleRange& train, const Validation& val) {
  const OperatingRange trained = operating_range(rec, cols, train.begin, train.end);
  report.fitted["operating_range"] = operating_range_json(trained);
  if (val.other)
    report.validation_beyond = beyond_range(trained, operating_range(*val.other, cols));
  else if (val.range)
    report.validation_beyond =
        beyond_range(trained, operating_range(rec, cols, val.range->begin, val.range->end));
}

FitReport fit_grey_box_model(const FitRequest& o, const Recording& rec, const SampleRange& train,
                             const Validation& val) {
  reject_prediction_mode(o);
  GreyboxOptions options;
  options.train = train;
  options.progress = o.progress;
  options.held = o.held;
  if (o.keep_inertance) options.min_inertance_gain = 0.0;
  options.motion_lead = o.motion_lead;
  const GreyboxFit fit = o.motion_leads.empty()
                             ? fit_greybox(rec, o.model, options)
                             : fit_searching_motion_lead(rec, o.model, options, o.motion_leads);
  FitReport report = grey_box_report(
      fit, rec, train, val, [&](const Recording& other) { return simulate_greybox(other, fit); });
  report.fitted = fit_model_json(fit, rec.meta);
  put_operating_range(report, drive_columns(fit), rec, train, val);
  report.tared_at_rest_s = fit.tared_rest_seconds;
  if (const std::optional<double> above = level_in_motion_above_rest(fit))
    for (const FittedParameter& p : fit.params)
      if (p.name == "offset") report.level_above_rest = std::make_pair(*above, p.unit);
  if (val.other) {  // simulate_greybox tares a validation recording at its own rest
    const lumped::GreyboxSetup setup = lumped::greybox_setup_for(*val.other, fit.setup.kind);
    if (const std::size_t rest = lumped::tared_rest(*val.other, setup); rest > 0)
      report.validation_tared_at_rest_s = val.other->t[rest] - val.other->t.front();
  }
  return report;
}

FitReport fit_valve_chain_model(const FitRequest& o, const Recording& rec, const SampleRange& train,
                                const Validation& val) {
  reject_prediction_mode(o);
  ValveChainFitOptions options;
  options.train = train;
  const ValveChainFit fit = fit_valve_chain(rec, options);
  FitReport report = grey_box_report(fit, rec, train, val, [&](const Recording& other) {
    return simulate_valve_chain(other, fit);
  });
  report.fitted = fit_model_json(fit, rec.meta);
  put_operating_range(report, drive_columns(fit), rec, train, val);
  return report;
}

/// Metrics as JSON; an unstable free run has no meaningful metrics: nulls and the reason.
nlohmann::json metrics_json(const Metrics& m, const std::optional<StabilityVerdict>& s) {
  if (s && !s->stable)
    return {{"fit_percent", nullptr},
            {"rmse_percent", nullptr},
            {"re", nullptr},
            {"stable", false},
            {"stability", s->reason}};
  nlohmann::json j = {
      {"fit_percent", m.fit_percent}, {"rmse_percent", m.rmse_percent}, {"re", m.re}};
  if (s) j["stable"] = true;
  return j;
}

std::vector<double> part(const std::vector<double>& v, const SampleRange& r) {
  return {v.begin() + static_cast<std::ptrdiff_t>(r.begin),
          v.begin() + static_cast<std::ptrdiff_t>(r.end)};
}

/// The repeatability (FIT of its own mean cycle, identify/repeatability.hpp) of samples `r` of
/// `rec`'s output under its motion drive (velocity or flow, else its first drive column).
std::optional<double> repeatability_of(const Recording& rec, const SampleRange& r) {
  std::string drive;
  for (const char* c : {"velocity", "flow"})
    if (drive.empty() && rec.columns.count(c)) drive = c;
  if (drive.empty() && !rec.meta.drive.empty()) drive = rec.meta.drive.front();
  if (drive.empty() || !rec.columns.count(drive)) return std::nullopt;
  return repeatability_percent(part(rec.t, r), part(lumped::column_without_glitches(rec, drive), r),
                               part(rec.column(rec.meta.output), r));
}

/// Where the recording repeats itself under a periodic drive: its repeatability, and the metrics
/// JSON gains it.
void add_repeatability(nlohmann::json& metrics, const std::optional<double>& repeatability) {
  if (repeatability) metrics["repeatability_percent"] = *repeatability;
}

void write_plot(const FitReport& r, const FitRequest& o, const Recording& rec,
                const SampleRange& train, const Validation& val) {
  const std::vector<double>& y = rec.column(rec.meta.output);
  std::vector<PlotSegment> segments{
      {"training", part(rec.t, train), part(y, train), r.train_output}};
  if (val.range)
    segments.push_back(
        {"validation", part(rec.t, *val.range), part(y, *val.range), r.validation_output});
  else if (val.other)
    segments.push_back(
        {"validation (" + std::filesystem::path(o.validate).filename().string() + ")", val.other->t,
         val.other->column(val.other->meta.output), r.validation_output});
  char title[256];
  std::snprintf(title, sizeof title, "%s on %s (%s): FIT %.1f %% training", r.model.c_str(),
                std::filesystem::path(o.recording).filename().c_str(),
                o.mode == EvalMode::simulation ? "simulation" : "one-step prediction",
                r.train.fit_percent);
  std::string heading = title;
  if (r.validation) {
    std::snprintf(title, sizeof title, ", %.1f %% validation", r.validation->fit_percent);
    heading += title;
  }
  // SI units of the recording format's output columns (shared/docs/recording-format.md).
  static const std::map<std::string, std::string> units{
      {"force", "N"},    {"pressure", "Pa"},     {"current", "A"},       {"voltage", "V"},
      {"flow", "m^3/s"}, {"flux_linkage", "Wb"}, {"temperature", "degC"}};
  const auto unit = units.find(rec.meta.output);
  const std::string label =
      rec.meta.output + (unit == units.end() ? std::string() : " [" + unit->second + "]");
  write_fit_plot(o.plot, heading, label, segments);
}

}  // namespace

FitRun run_fit(const FitRequest& o) {
  const bool black_box = is_black_box_model(o.model);
  const bool valve_chain = o.model == "valve-chain";
  if (!black_box && !valve_chain && !is_greybox_model(o.model)) {
    throw InputError("--model '" + o.model + "' is not a model rheomag knows; did you mean '" +
                     closest_model_name(o.model, known_model_names()) + "'?");
  }
  if (!o.held.empty() && !is_greybox_model(o.model))
    throw InputError("--hold: holds a parameter of a grey-box model; '" + o.model +
                     "' is not one (" +
                     (valve_chain ? "the valve-chain fit" : "a black-box model") + ")");
  if (o.motion_lead != 0.0 && !is_greybox_model(o.model))
    throw InputError("--motion-lead: a lead of the motion drive applies to grey-box models; '" +
                     o.model + "' is not one (" +
                     (valve_chain ? "the valve-chain fit" : "a black-box model") +
                     "); give auto or 0");
  if (!o.plot.empty() && !gnuplot_available())
    throw InputError("--plot needs gnuplot on PATH (Debian package gnuplot-nox)");
  Recording rec = o.load_recording(o.recording);
  const std::size_t n = rec.t.size();
  SampleRange train =
      o.train.empty() ? SampleRange{0, n} : lumped::parse_sample_range(o.train, n, "--train");
  Validation val = read_validation(o, rec, train);
  // Memory and time grow with the samples: a recording too long is thinned (the ranges, given
  // in its own samples, follow), and so is a validation recording.
  std::vector<std::string> thinning;
  if (const std::size_t factor = lumped::thinning_factor(n); factor > 1) {
    rec = lumped::every_nth_sample(rec, factor);
    train = lumped::thinned_range(train, factor);
    if (val.range) val.range = lumped::thinned_range(*val.range, factor);
    thinning.push_back(o.recording + ": " + lumped::thinning_note(n, factor));
    if (train.begin >= train.end)
      throw InputError("--train " + o.train + ": no sample left after thinning the recording to " +
                       thinning.back());
  }
  if (val.other) {
    const std::size_t other_n = val.other->t.size();
    if (const std::size_t factor = lumped::thinning_factor(other_n); factor > 1) {
      val.other = lumped::every_nth_sample(*val.other, factor);
      thinning.push_back(o.validate + ": " + lumped::thinning_note(other_n, factor));
    }
  }
  if (o.progress)
    for (const std::string& note : thinning)
      o.progress({"recording thinned", 0, 0, 0, note, false});
  rec.require_varying(rec.meta.output, train.begin, train.end);
  const FitReport report = black_box     ? fit_black_box_model(o, rec, train, val)
                           : valve_chain ? fit_valve_chain_model(o, rec, train, val)
                                         : fit_grey_box_model(o, rec, train, val);
  if (!o.plot.empty()) write_plot(report, o, rec, train, val);
  FitRun run{o, std::move(rec), train, val, report, std::nullopt, std::nullopt, thinning};
  run.train_repeatability = repeatability_of(run.recording, train);
  if (report.validation)
    run.validation_repeatability =
        val.other ? repeatability_of(*val.other, SampleRange{0, val.other->t.size()})
                  : repeatability_of(run.recording, *val.range);
  return run;
}

nlohmann::json fit_run_json(const FitRun& run) {
  const FitReport& report = run.report;
  const FitRequest& o = run.request;
  const SampleRange& train = run.train;
  const Validation& val = run.validation;
  nlohmann::json j = report.fitted;
  j["params"] = report.params;
  if (report.standard_errors.is_object()) j["standard_errors"] = report.standard_errors;
  j["train"] = metrics_json(report.train, report.train_stability);
  add_repeatability(j["train"], run.train_repeatability);
  j["train_range"] = {train.begin, train.end};
  const auto tare = [](double s) { return s > 0.0 ? nlohmann::json(s) : nlohmann::json(); };
  j["train"]["tared_at_rest_s"] = tare(report.tared_at_rest_s);
  j["validation"] = report.validation
                        ? metrics_json(*report.validation, report.validation_stability)
                        : nlohmann::json(nullptr);
  if (report.validation) {
    add_repeatability(j["validation"], run.validation_repeatability);
    if (val.other) j["validation"]["tared_at_rest_s"] = tare(report.validation_tared_at_rest_s);
    if (report.fitted.contains("operating_range"))
      j["validation"]["beyond_training"] = range_excess_json(report.validation_beyond);
  }
  if (val.range) j["validation_range"] = {val.range->begin, val.range->end};
  if (val.other) j["validation_file"] = o.validate;
  j["mode"] = o.mode == EvalMode::simulation ? "simulation" : "prediction";
  if (!run.thinning.empty()) j["thinned"] = run.thinning;
  return j;
}

void write_fit_run_text(const FitRun& run, std::ostream& out) {
  const FitReport& r = run.report;
  const FitRequest& o = run.request;
  const SampleRange& train = run.train;
  const Validation& val = run.validation;
  auto line = [&out](const std::string& what, const Metrics& m,
                     const std::optional<StabilityVerdict>& s) {
    if (s && !s->stable) {
      out << format_text("%-34s UNSTABLE in free-run simulation: %s (no FIT reported)\n",
                         what.c_str(), s->reason.c_str());
      return;
    }
    out << format_text("%-34s FIT %7.2f %%   RMSE %7.2f %%   RE %.4f\n", what.c_str(),
                       m.fit_percent, m.rmse_percent, m.re);
  };
  out << format_text("model %s (%s mode)\n", r.model.c_str(),
                     o.mode == EvalMode::simulation ? "simulation" : "prediction");
  for (const std::string& note : run.thinning) out << "samples: " << note << "\n";
  if (const auto setup = r.fitted.find("setup");
      setup != r.fitted.end() && setup->contains("motion_lead_s"))
    out << format_text("motion lead %.1f ms: the %s drive read this much later than recorded\n",
                       1e3 * setup->at("motion_lead_s").get<double>(),
                       setup->at("motion_column").get<std::string>().c_str());
  const auto repeatability = [&out](const std::optional<double>& rep) {
    if (rep)
      out << format_text("%-34s FIT %7.2f %%   (its own mean cycle: no periodic model beats it)\n",
                         "  repeatability", *rep);
  };
  const auto tared = [&out](double seconds) {
    if (seconds > 0.0)
      out << format_text(
          "  (the model's output tared to the recording's level over its first "
          "%.2f s, at rest)\n",
          seconds);
  };
  line("train " + range_text(train), r.train, r.train_stability);
  tared(r.tared_at_rest_s);
  if (r.level_above_rest && r.tared_at_rest_s > 0.0)
    out << format_text("  (in motion its level is %.4g %s above the rest's: the offset)\n",
                       r.level_above_rest->first, r.level_above_rest->second.c_str());
  repeatability(run.train_repeatability);
  if (r.validation) {
    line("validation " + (val.range ? range_text(*val.range) : o.validate), *r.validation,
         r.validation_stability);
    if (val.other) tared(r.validation_tared_at_rest_s);
    for (const RangeExcess& e : r.validation_beyond)
      out << "  beyond the training part's drive: " << e.text() << "\n";
    repeatability(run.validation_repeatability);
  }
  out << format_text("parameters:\n");
  if (!r.parameters.empty()) {  // grey-box: SI units, standard errors and the remark rule
    for (const FittedParameter& p : r.parameters) {
      out << format_text("  %-28s %12.6g", p.name.c_str(), p.value);
      if (p.standard_error && std::isfinite(*p.standard_error))
        out << format_text(" +- %-10.3g", *p.standard_error);
      else
        out << format_text("    %-10s", "");
      const std::string remark = parameter_remark(p);
      out << format_text(" %s%s\n", p.unit.c_str(),
                         remark.empty() ? "" : ("  (" + remark + ")").c_str());
    }
    return;
  }
  for (const auto& [name, value] : r.params.items()) {
    out << format_text("  %-28s %.6g", name.c_str(), value.get<double>());
    if (r.standard_errors.is_object() && r.standard_errors.contains(name) &&
        r.standard_errors[name].is_number())
      out << format_text("  +- %.3g", r.standard_errors[name].get<double>());
    out << format_text("\n");
  }
}

}  // namespace rheomag::identify
