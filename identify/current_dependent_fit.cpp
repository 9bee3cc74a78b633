// Family fits: join recordings, fit one grey-box model, evaluate it on every member.

#include "identify/current_dependent_fit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <future>
#include <numeric>

#include "core/error.hpp"
#include "identify/family_cross_validation.hpp"
#include "identify/fit_model_json.hpp"
#include "identify/motion_lead_search.hpp"
#include "identify/multistart_fit.hpp"
#include "identify/repeatability.hpp"
#include "lumped/motion_glitches.hpp"
#include "lumped/output_smoothing.hpp"

namespace rheomag::identify {

FamilyMember evaluate_family_member(const lumped::Recording& rec, const GreyboxFit& fit) {
  FamilyMember m;
  m.csv_path = rec.csv_path;
  if (!fit.setup.field_column.empty()) {
    const auto& u = rec.column(fit.setup.field_column);
    m.field = std::accumulate(u.begin(), u.end(), 0.0) / static_cast<double>(u.size());
  }
  m.simulated = simulate_greybox(rec, fit);
  m.mean_removed = lumped::output_mean_removed(rec.column(fit.setup.output_column));
  if (const std::size_t rest = lumped::tared_rest(rec, fit.setup); rest > 0)
    m.rest_seconds = rec.t[rest] - rec.t.front();
  m.metrics = lumped::compute_metrics(rec.column(fit.setup.output_column), m.simulated);
  // The motion as the model read it (a glitch would cut a cycle or a stroke in two).
  const std::vector<double> motion = lumped::column_without_glitches(rec, fit.setup.motion_column);
  m.repeatability = repeatability_percent(rec.t, motion, rec.column(fit.setup.output_column));
  m.regimes = residual_regimes(motion, rec.column(fit.setup.output_column), m.simulated);
  return m;
}

FamilyMember predict_family_member(const lumped::Recording& rec, const GreyboxFit& fit) {
  FamilyMember m = evaluate_family_member(rec, fit);
  m.band = prediction_band(rec, fit);
  m.level = calibrate_level(rec.t, lumped::column_without_glitches(rec, fit.setup.motion_column),
                            rec.column(fit.setup.output_column), m.simulated);
  return m;
}

/// Refuses a training recording given twice: the same file under two names (on disk), or the
/// same samples under two names.
static void refuse_duplicate_recordings(const std::vector<lumped::Recording>& training) {
  // One test counted twice shrinks the between-recording standard errors (23 -> 13.2 in issue
  // 36): the same file under two names, or the same samples under two files, is refused.
  for (std::size_t j = 1; j < training.size(); ++j)
    for (std::size_t i = 0; i < j; ++i) {
      const lumped::Recording &a = training[i], &b = training[j];
      std::error_code ec_a, ec_b;
      const auto real_a = std::filesystem::weakly_canonical(a.csv_path, ec_a);
      const auto real_b = std::filesystem::weakly_canonical(b.csv_path, ec_b);
      const bool same_file = std::filesystem::is_regular_file(a.csv_path, ec_a) &&
                             std::filesystem::is_regular_file(b.csv_path, ec_b) && real_a == real_b;
      if (same_file || (a.t == b.t && a.columns == b.columns))
        throw InputError(b.csv_path + ": " +
                         (same_file
                              ? "the same file as " + a.csv_path + " (" + real_a.string() + ")"
                              : "the same samples as " + a.csv_path + " (every column equal)") +
                         "; expected each training recording once (a duplicate counts one test "
                         "twice and understates the spread between recordings)");
    }
}

/// Refuses a current-dependent model on training recordings that all have one field level.
static void check_field_levels(const std::vector<lumped::Recording>& training,
                               const std::string& model) {
  const lumped::Recording& first = training.front();
  lumped::PhenoKind kind;
  if (!lumped::parse_pheno_kind(model, kind)) return;  // fit_greybox_family names the unknown model
  const lumped::GreyboxSetup setup = lumped::greybox_setup_for(first, kind);
  if (setup.field_column.empty()) return;  // no field input: the model is not current-dependent
  // The field terms are identifiable only if the field takes two or more values in the family.
  double lo = 1e300, hi = -1e300;
  for (const lumped::Recording& r : training)
    for (double u : r.column(setup.field_column)) {
      lo = std::min(lo, u);
      hi = std::max(hi, u);
    }
  if (!(hi - lo > 1e-3 * std::max({std::abs(lo), std::abs(hi), 1e-12})))
    throw InputError("fit-family --model " + model + ": the '" + setup.field_column +
                     "' column is " + std::to_string(lo) + " in every training recording (" +
                     first.csv_path +
                     ", ...); the model's field terms need recordings at two or "
                     "more field levels");
}

void check_family(const std::vector<lumped::Recording>& training,
                  const std::vector<lumped::Recording>& prediction, const std::string& model) {
  if (training.empty()) throw InputError("fit-family: no training recordings given");
  const lumped::Recording& first = training.front();
  const auto kind_text = [](const lumped::Recording& r) {
    return r.meta.rig.kind ? "'" + std::string(lumped::kRigKindNames.name(*r.meta.rig.kind)) + "'"
                           : std::string("(none)");
  };
  const auto same_kind = [&](const lumped::Recording& r) {
    if (r.meta.rig.kind != first.meta.rig.kind)
      throw InputError(r.csv_path + ": [rig] kind " + kind_text(r) + " differs from " +
                       kind_text(first) + " of " + first.csv_path +
                       "; a family is one device on one rig");
    if (r.meta.drive != first.meta.drive || r.meta.output != first.meta.output)
      throw InputError(r.csv_path + ": drive/output columns differ from " + first.csv_path +
                       "; a family fit needs recordings of the same kind");
  };
  for (const lumped::Recording& r : training) same_kind(r);
  for (const lumped::Recording& r : prediction) same_kind(r);
  check_field_levels(training, model);  // the model's own requirement is named first
  refuse_duplicate_recordings(training);
}

lumped::Recording join_recordings(const std::vector<lumped::Recording>& recs, int decimation) {
  if (recs.empty()) throw InputError("join_recordings: no recordings given");
  if (decimation < 1)
    throw InputError("decimation must be at least 1, got " + std::to_string(decimation));
  const lumped::Recording& first = recs.front();
  lumped::Recording joined;
  joined.meta = first.meta;
  joined.csv_path = first.csv_path;
  for (const auto& [name, values] : first.columns) {
    (void)values;
    const bool everywhere = std::all_of(recs.begin(), recs.end(), [&](const lumped::Recording& r) {
      return r.columns.count(name);
    });
    if (everywhere) joined.columns[name];
  }
  for (const lumped::Recording& r : recs) {
    if (r.meta.drive != first.meta.drive || r.meta.output != first.meta.output)
      throw InputError(r.csv_path + ": drive/output columns differ from " + first.csv_path +
                       "; a family fit needs recordings of the same kind");
    if (r.t.size() < 2) throw InputError(r.csv_path + ": fewer than 2 samples");
    const double step = (r.t[1] - r.t[0]) * decimation;
    const double shift = joined.t.empty() ? -r.t.front() : joined.t.back() + step - r.t.front();
    for (std::size_t i = 0; i < r.t.size(); i += static_cast<std::size_t>(decimation)) {
      joined.t.push_back(r.t[i] + shift);
      for (auto& [name, values] : joined.columns) values.push_back(r.columns.at(name)[i]);
    }
  }
  return joined;
}

namespace {

/// Alternates the per-recording viscosity factors (each fitted with the shared parameters held)
/// and the joint fit (the factors held, started from the last fit) for the nuisance's rounds;
/// updates `fit` and returns the factors it was fitted with (geometric mean 1).
std::vector<double> fit_with_viscosity_factors(const std::vector<lumped::Recording>& training,
                                               const FamilyFitOptions& options, GreyboxFit& fit) {
  const ViscosityNuisance& nuisance = *options.viscosity_nuisance;
  std::vector<double> factors(training.size(), 1.0);
  for (int round = 0; round < nuisance.rounds; ++round) {
    for (std::size_t r = 0; r < training.size(); ++r)
      factors[r] =
          fit_viscosity_factor(training[r], with_viscosity_factor(fit, factors[r]), nuisance) *
          factors[r];
    // Keep the factors inside their bounds after centring: clamp, centre, clamp again.
    centre_viscosity_factors(factors, fit);
    for (double& f : factors) f = std::clamp(f, nuisance.lower, nuisance.upper);
    // The rounds keep the first fit's decisions: what it held of its own accord stays held.
    GreyboxOptions refit = warm_refit_options(options.greybox, fit, options.greybox.max_iterations);
    refit.viscous_factors = factors;
    refit.motion_lead = fit.setup.motion_lead;
    const GreyboxFit before = fit;
    fit = fit_greybox_family(training, fit.model, refit, options.decimation);
    keep_fit_decisions(before, fit);
  }
  return factors;
}

}  // namespace

GreyboxFit fit_family(const std::vector<lumped::Recording>& recs, const std::string& model,
                      const GreyboxOptions& greybox, const FamilyFitOptions& options) {
  if (options.motion_leads.empty())
    return fit_greybox_family(recs, model, greybox, options.decimation);
  return fit_family_searching_motion_lead(recs, model, greybox, options.decimation,
                                          options.motion_leads);
}

FamilyFit fit_current_dependent(const std::vector<lumped::Recording>& training,
                                const std::string& model,
                                const std::vector<lumped::Recording>& prediction,
                                const FamilyFitOptions& options) {
  check_family(training, prediction, model);
  if (options.cross_validate) check_cross_validation(training, model);  // before the long fits
  FamilyFit out;
  // The cross-validation's fits do not depend on the main fit: on more than one thread they run
  // beside it, and the cores its starts leave idle (one start ends before the other) go to them.
  std::future<std::vector<FamilyMember>> held_out;
  if (options.cross_validate)
    held_out = std::async(
        fit_threads(options.greybox.threads) > 1 ? std::launch::async : std::launch::deferred,
        [&] { return cross_validate_family(training, model, options); });
  const auto start = std::chrono::steady_clock::now();
  out.fit = fit_family(training, model, options.greybox, options);
  std::vector<double> factors;
  if (options.viscosity_nuisance) factors = fit_with_viscosity_factors(training, options, out.fit);
  // Each recording simulated at its full rate with the fitted parameters.
  const std::size_t members = training.size() + prediction.size();
  const auto evaluate = [&](const lumped::Recording& r, std::vector<FamilyMember>& into) {
    into.push_back(&into == &out.training ? evaluate_family_member(r, out.fit)
                                          : predict_family_member(r, out.fit));
    if (!options.greybox.progress) return;
    ProgressEvent e;
    e.stage = "simulating every recording with the fitted " + out.fit.model;
    e.done = static_cast<double>(out.training.size() + out.predicted.size());
    e.total = static_cast<double>(members);
    e.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    options.greybox.progress(e);
  };
  for (std::size_t r = 0; r < training.size(); ++r) {
    if (factors.empty()) {
      evaluate(training[r], out.training);
      continue;
    }
    out.training.push_back(
        evaluate_family_member(training[r], with_viscosity_factor(out.fit, factors[r])));
    out.training.back().viscosity_factor = factors[r];
  }
  const DriveColumns cols = drive_columns(out.fit);
  for (const lumped::Recording& r : training)
    out.trained = span(out.trained, operating_range(r, cols));
  for (const lumped::Recording& r : prediction) {
    evaluate(r, out.predicted);
    out.predicted.back().beyond = beyond_range(out.trained, operating_range(r, cols));
  }
  if (held_out.valid()) out.held_out = held_out.get();
  return out;
}

}  // namespace rheomag::identify
