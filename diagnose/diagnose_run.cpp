// The diagnosis of one recording: calibrate the baseline, locate the mismatch, forward-select
// candidate physics, re-fit the accepted ones together and report what is left.

#include "diagnose/diagnose_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "diagnose/candidate.hpp"
#include "diagnose/candidate_registry.hpp"
#include "diagnose/diagnose_change.hpp"
#include "diagnose/diagnose_clock.hpp"
#include "diagnose/diagnose_evidence.hpp"
#include "diagnose/diagnose_findings.hpp"
#include "diagnose/diagnose_noise.hpp"
#include "diagnose/diagnose_nuisances.hpp"
#include "diagnose/diagnose_rejection.hpp"
#include "diagnose/diagnose_selection.hpp"
#include "diagnose/diagnose_text.hpp"
#include "diagnose/diagnose_ties.hpp"
#include "lumped/metrics.hpp"
#include "lumped/recording_excerpt.hpp"

namespace rheomag::diagnose {

namespace {

constexpr std::size_t kMinSamples = 100;

/// Rejects recordings that cannot support a diagnosis, saying why.
void check_informative(const DiagnosisModel& model) {
  const auto& rec = model.recording();
  const std::string name = rec.csv_path.empty() ? std::string("recording") : rec.csv_path;
  if (rec.t.size() < kMinSamples)
    throw InputError(name + ": too short to diagnose: " + std::to_string(rec.t.size()) +
                     " samples, at least " + std::to_string(kMinSamples) + " needed");
  const auto& y = model.measured();
  const auto [lo, hi] = std::minmax_element(y.begin(), y.end());
  const double span = *hi - *lo;
  if (!(span > 1e-9 * std::max(std::abs(*hi), std::abs(*lo))) || span == 0.0)
    throw InputError(name + ": the output column '" + model.output_column() +
                     "' is flat; nothing to diagnose");
  bool any_moving = false;
  for (const auto& c : rec.meta.drive) {
    auto it = rec.columns.find(c);
    if (it == rec.columns.end()) continue;
    const auto [a, b] = std::minmax_element(it->second.begin(), it->second.end());
    if (*b > *a) any_moving = true;
  }
  if (!any_moving)
    throw InputError(name +
                     ": every drive column is constant; the recording is too flat to "
                     "diagnose");
}

/// The note on the final fit's output delay: held at 0 where the data do not require it, or kept.
std::string delay_alignment_note(const DelayAlignment& a, double margin) {
  const std::string delay = value_text(1e3 * a.delay, "ms");
  if (!a.aligned)
    return "output delay kept at " + delay + " in the final fit: free, it lowers BIC by " +
           fmt(a.delta_bic) + " against the channels aligned (more than the margin " + fmt(margin) +
           ")";
  return "output delay held at 0 in the final fit: the data do not require it (the fitted " +
         delay + " delay lowers BIC by " + fmt(a.delta_bic) + ", not more than the margin " +
         fmt(margin) +
         "); where the delay and a finding are one force on this drive, the "
         "finding's size takes what the delay held (see its size line)";
}

/// Each finding linear in its size gets its size's trade with the output delay and the
/// applicable linear candidates of the same shape, measured on the final fit `fit`.
void add_size_sensitivities(const DiagnosisModel& model, const ModelFit& fit,
                            const DiagnoseOptions& options, std::vector<Finding>& findings) {
  if (findings.empty()) return;
  std::vector<const Candidate*> linear;
  for (const Candidate* c : applicable_candidates(model))
    if (c->linear_in_size(model)) linear.push_back(c);
  const auto sensitivities =
      size_sensitivities(model, fit, linear, options.max_iterations, options.threads);
  for (Finding& f : findings)
    for (std::size_t i = 0; i < fit.effects.size(); ++i)
      if (fit.effects[i] == f.effect) f.sensitivity = sensitivities[i];
}

/// Share of the residual energy above the white-noise floor n sigma^2.
Unexplained unexplained_of(const std::vector<double>& residual, double baseline_sse, double sigma) {
  Unexplained u;
  double sse = 0.0;
  for (double r : residual) sse += r * r;
  const auto n = static_cast<double>(residual.size());
  u.noise_sigma = sigma;
  u.residual_rms = std::sqrt(sse / n);
  const double above = std::max(sse - n * sigma * sigma, 0.0);
  u.share = sse > 0.0 ? above / sse : 0.0;
  u.baseline_share = baseline_sse > 0.0 ? above / baseline_sse : 0.0;
  return u;
}

/// The `length` consecutive samples (starting on a grid of length/4, or ending at the last
/// sample) whose baseline residual energy is largest: where the baseline misses most is where
/// what it lacks shows, and a stretch at rest carries no evidence.
lumped::SampleRange representative_excerpt(const std::vector<double>& residual,
                                           std::size_t length) {
  const std::size_t n = residual.size();
  std::vector<double> energy(n + 1, 0.0);  // cumulative squared residual
  for (std::size_t k = 0; k < n; ++k) energy[k + 1] = energy[k] + residual[k] * residual[k];
  const std::size_t step = std::max<std::size_t>(length / 4, 1);
  lumped::SampleRange best{0, length};
  double best_energy = -1.0;
  for (std::size_t b = 0;; b += step) {
    const std::size_t begin = std::min(b, n - length);
    const double e = energy[begin + length] - energy[begin];
    if (e > best_energy) best_energy = e, best = {begin, begin + length};
    if (begin == n - length) break;
  }
  return best;
}

/// True when the stated oil's compliance may fit `model`'s recording better than the calibrated
/// stiff `baseline`. A recording longer than `selection_samples` is judged on its most
/// informative excerpt (both calibrated there), so that the whole record is calibrated a second
/// time only when the compliance wins there.
bool compliance_fits_better(const DiagnosisModel& model, const ModelFit& baseline,
                            std::size_t selection_samples, const FitSettings& calib) {
  const auto& y = model.measured();
  if (selection_samples == 0 || y.size() <= selection_samples) return true;
  std::vector<double> residual(y.size());
  for (std::size_t k = 0; k < y.size(); ++k) residual[k] = y[k] - baseline.prediction[k];
  const auto selection = representative_excerpt(residual, selection_samples);
  const DiagnosisModel part(lumped::excerpt(model.recording(), selection), nullptr,
                            model.sampling(), model.current_path_wanted());
  const auto stiff = fit_model(part, {}, baseline.values, calib);
  const auto compliant = fit_model(part.with_oil_compliance(0.0), {}, baseline.values, calib);
  return compliant.sse < stiff.sse;
}

/// The note of a fitted-model baseline: the candidates that sit inside the rig's loops.
std::string fitted_model_note() {
  std::vector<std::string> names;
  for (const Candidate* c : candidates_in_trial_order(false))
    if (!c->composes_with_fitted_model()) names.push_back(c->name());
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i)
    list += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  return "the baseline is a fitted model: " + list +
         " sit inside the rig's hydraulic or electric loop and are not candidates on it";
}

/// One recording's diagnosis and the model it was made on (kept for a reference comparison).
struct OneDiagnosis {
  Diagnosis d;
  std::unique_ptr<DiagnosisModel> model;
};

/// Diagnoses one recording (DiagnoseOptions::reference aside).
OneDiagnosis diagnose_one(const lumped::Recording& recording, const DiagnoseOptions& options) {
  Clock clock(options.progress);
  // Memory and time grow with the samples: a recording too long is thinned, and says so.
  const std::size_t factor = lumped::thinning_factor(recording.t.size());
  const lumped::Recording thinned =
      lumped::every_nth_sample(factor > 1 ? recording : lumped::Recording{}, factor);
  const lumped::Recording& rec = factor > 1 ? thinned : recording;
  const ModelBaseline* fitted = options.baseline_model ? &*options.baseline_model : nullptr;
  auto chosen =
      std::make_unique<DiagnosisModel>(rec, fitted, DriveSampling::linear, options.current_path);
  check_informative(*chosen);
  Diagnosis d;
  d.recording = rec.csv_path;

  // 1. Baseline: calibrate the static parameters and nuisances, with the drive sampling
  // convention (linear or held between samples) that fits better.
  FitSettings calib;
  calib.max_iterations = 50;
  calib.threads = options.threads;
  auto calibrate = [&](const DiagnosisModel& m) {
    return fit_model(m, {}, nuisance_start(m, options.threads), calib);
  };
  d.baseline = calibrate(*chosen);
  if (chosen->oil_compliance_optional() &&
      compliance_fits_better(*chosen, d.baseline, options.selection_samples, calib)) {
    // The stated oil's compliance: kept where it fits better than a stiff fluid.
    auto compliant_fit = calibrate(chosen->with_oil_compliance(0.0));
    if (compliant_fit.sse < d.baseline.sse) {
      const double gain = lumped::fit_percent(chosen->measured(), compliant_fit.prediction) -
                          lumped::fit_percent(chosen->measured(), d.baseline.prediction);
      chosen = std::make_unique<DiagnosisModel>(chosen->with_oil_compliance(gain));
      d.baseline = std::move(compliant_fit);
    }
  }
  double other_fit_percent = std::numeric_limits<double>::quiet_NaN();
  if (chosen->can_hold()) {
    auto held = std::make_unique<DiagnosisModel>(chosen->held());
    auto held_fit = calibrate(*held);
    if (held_fit.sse < d.baseline.sse) {
      std::swap(chosen, held);
      std::swap(d.baseline, held_fit);
    }
    other_fit_percent = lumped::fit_percent(chosen->measured(), held_fit.prediction);
  }
  const DiagnosisModel& model = *chosen;
  d.output_column = model.output_column();
  d.t = rec.t;
  d.measured = model.measured();
  const auto& y = model.measured();
  const std::size_t n = y.size();
  d.baseline_fit_percent = lumped::fit_percent(y, d.baseline.prediction);
  d.includes = model.includes();
  d.nuisance = nuisance_of(model, d.baseline);
  d.nuisance.sampling_fit_gain = d.baseline_fit_percent - other_fit_percent;
  clock.stage("baseline calibration");

  // 2. Locate.
  std::vector<double> residual(n);
  for (std::size_t k = 0; k < n; ++k) residual[k] = y[k] - d.baseline.prediction[k];
  d.mismatch = locate_mismatch(model.recording(), residual);
  d.baseline_stats =
      residual_statistics(model.recording(), rec.meta.drive, y, d.baseline.prediction);
  // The noise floor: the white part of the baseline's residual (output sensor noise and drive
  // noise the static map passes through); no candidate can explain it.
  const double sigma = noise_sigma(residual);
  const Evidence evidence = evidence_of(d.baseline.prediction, sigma);

  // 3. Name: forward selection, on the whole recording or, when it is long, on its most
  // informative excerpt (the cost rule; the final re-fit below uses every sample).
  ModelFit current = d.baseline;
  if (options.selection_samples > 0 && n > options.selection_samples) {
    d.selection = representative_excerpt(residual, options.selection_samples);
    DiagnosisModel part(lumped::excerpt(rec, d.selection), fitted, model.sampling(),
                        options.current_path);
    if (model.oil_compliance() && !part.oil_compliance()) part = part.with_oil_compliance(0.0);
    const auto part_baseline = fit_model(part, {}, d.baseline.values, calib);
    std::vector<double> part_residual(d.selection.size());
    for (std::size_t k = 0; k < part_residual.size(); ++k)
      part_residual[k] = part.measured()[k] - part_baseline.prediction[k];
    const double part_sigma = noise_sigma(part_residual);
    clock.stage("excerpt calibration");
    const auto selected = forward_select(
        part, part_baseline, evidence_of(part_baseline.prediction, part_sigma), options, d, clock);
    if (!d.findings.empty()) {
      current.effects = selected.effects;
      current.values = selected.values;
      current.sse = std::numeric_limits<double>::infinity();  // not yet simulated on every sample
    }
    d.notes.push_back("long recording (" + std::to_string(n) +
                      " samples): candidates were screened, fitted and checked on samples " +
                      std::to_string(d.selection.begin) + ":" + std::to_string(d.selection.end) +
                      " (the " + std::to_string(d.selection.size()) +
                      "-sample stretch with the largest baseline residual energy); the final "
                      "joint re-fit and FIT use every sample");
  } else {
    current = forward_select(model, std::move(current), evidence, options, d, clock);
  }

  // Re-fit all accepted effects together, with the nuisances free again (they were held while
  // the candidates were compared); where that does not improve, keep the last forward step's fit
  // (with its standard errors). Then each tie of the selection is decided again in that model.
  if (!d.findings.empty()) {
    FitSettings final_settings;
    final_settings.max_iterations = 2 * options.max_iterations;
    final_settings.threads = options.threads;
    auto refit = fit_model(model, current.effects, current.values, final_settings);
    if (refit.sse > current.sse) {
      final_settings.max_iterations = 0;
      refit = fit_model(model, current.effects, current.values, final_settings);
    }
    current = std::move(refit);
    final_settings.max_iterations = 2 * options.max_iterations;
    revisit_ties(model, current, final_settings, options.bic_margin, d);
    drop_faded_findings(model, current, evidence, options, d);
    if (options.align_delay && !d.findings.empty()) {
      const auto a =
          align_unrequired_delay(model, current, final_settings, options.align_delay_margin);
      if (a.tried) d.notes.push_back(delay_alignment_note(a, options.align_delay_margin));
    }
  }
  clock.stage("joint re-fit");
  d.final_fit = current;
  d.final_fit_percent = lumped::fit_percent(y, current.prediction);
  d.final_stats = residual_statistics(model.recording(), rec.meta.drive, y, current.prediction);
  for (std::size_t k = 0; k < n; ++k) residual[k] = y[k] - current.prediction[k];
  d.final_mismatch = locate_mismatch(model.recording(), residual);
  d.unexplained = unexplained_of(residual, d.baseline.sse, sigma);
  d.final_nuisance = nuisance_of(model, current);
  d.final_nuisance.sampling_fit_gain = d.nuisance.sampling_fit_gain;
  std::size_t offset = model.static_params().size();
  for (auto& f : d.findings) {
    for (const auto& p : f.effect->params(model)) {
      f.param_names.push_back(p.name);
      f.param_units.push_back(p.unit);
      f.params.push_back(current.values[offset]);
      f.standard_errors.push_back(current.standard_errors[offset]);
      ++offset;
    }
    f.derived = f.effect->derived_params(model, f.params);
    f.evidence = finding_evidence(f, d, current);
  }
  add_size_sensitivities(model, current, options, d.findings);
  if (!d.findings.empty()) clock.stage("size sensitivities");
  const bool chamber_finding = std::any_of(d.findings.begin(), d.findings.end(), [](const auto& f) {
    return f.effect->uses_chamber_volume();
  });
  if (!model.chamber_volume_given() && chamber_finding)
    d.notes.push_back(
        "[rig] chamber_volume not given: compressibility assumed 2e-5 m^3 of oil "
        "per chamber");
  if (factor > 1)
    d.notes.push_back("recording thinned to " + lumped::thinning_note(recording.t.size(), factor));
  for (const std::string& glitch : model.motion_glitch_notes()) d.notes.push_back(glitch);
  if (model.fitted_baseline()) d.notes.push_back(fitted_model_note());
  if (fitted)  // beyond its training drive the baseline extrapolates: its mismatch is suspect
    d.beyond_training = identify::beyond_fitted_range(fitted->model, recording);
  for (const identify::RangeExcess& e : d.beyond_training)
    d.notes.push_back("the recording's drive is beyond the baseline model's training drive (" +
                      e.text() +
                      "): a mismatch there may be the model's extrapolation, not missing "
                      "physics");
  if (model.constant_field())
    d.notes.push_back("the recording has no coil input: the field is taken as constant");
  if (d.findings.empty() && !d.baseline_stats.white)
    d.notes.push_back("the residual is not white but no candidate explains it significantly");
  return {std::move(d), std::move(chosen)};
}

/// `options` for the reference recording: without a reference, progress stages prefixed.
DiagnoseOptions reference_options(const DiagnoseOptions& options) {
  DiagnoseOptions r = options;
  r.reference.reset();
  if (options.progress)
    r.progress = [progress = options.progress](const ProgressEvent& e) {
      ProgressEvent named = e;
      named.stage = "reference: " + e.stage;
      progress(named);
    };
  return r;
}

}  // namespace

Diagnosis diagnose(const lumped::Recording& recording, const DiagnoseOptions& options) {
  if (options.reference && !options.baseline_model)
    throw InputError(
        "--reference: a reference recording is compared through its effects' sizes against a "
        "fitted model, so it needs one as the baseline: --baseline MODEL.json (from 'rheomag "
        "fit --json' or 'fit-family --json')");
  OneDiagnosis today = diagnose_one(recording, options);
  if (options.reference) {
    const OneDiagnosis before = diagnose_one(*options.reference, reference_options(options));
    Clock clock(options.progress);
    Diagnosis& d = today.d;
    d.reference = compare_with_reference(*today.model, d, *before.model, before.d, options);
    clock.stage("comparison with the reference");
    std::string one_sided;
    for (const std::string& name : d.reference->sized_on_one)
      one_sided += (one_sided.empty() ? "" : ", ") + name;
    if (!one_sided.empty())
      d.notes.push_back("not compared with the reference (sized on only one of the two): " +
                        one_sided);
  }
  return std::move(today.d);
}

}  // namespace rheomag::diagnose
