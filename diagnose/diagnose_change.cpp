// The change between a reference recording's diagnosis and today's, effect by effect.

#include "diagnose/diagnose_change.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "diagnose/candidate_registry.hpp"
#include "diagnose/diagnose_findings.hpp"
#include "diagnose/size_sensitivity.hpp"

namespace rheomag::diagnose {

namespace {

using Effects = std::vector<const Candidate*>;

bool holds(const Effects& effects, const Candidate* c) {
  return std::find(effects.begin(), effects.end(), c) != effects.end();
}

/// The effects both recordings are sized with: what either named, then every candidate linear
/// in its size that applies to both models.
Effects comparison_effects(const DiagnosisModel& today_model, const Diagnosis& today,
                           const DiagnosisModel& reference_model, const Diagnosis& reference) {
  Effects effects;
  for (const Diagnosis* d : {&today, &reference})
    for (const Finding& f : d->findings)
      if (!holds(effects, f.effect)) effects.push_back(f.effect);
  const Effects there = applicable_candidates(reference_model);
  for (const Candidate* c : applicable_candidates(today_model))
    if (c->linear_in_size(today_model) && c->linear_in_size(reference_model) && holds(there, c) &&
        !holds(effects, c))
      effects.push_back(c);
  return effects;
}

/// The start of a recording's comparison fit: its final fit's static parameters and nuisances,
/// and for each effect its final values where it named it, else 0 for a size linear in it, else
/// the other recording's named values, else the candidate's nominal ones.
std::vector<double> comparison_start(const DiagnosisModel& model, const ModelFit& own,
                                     const ModelFit& other, const Effects& effects) {
  const std::size_t n_static = model.static_params().size();
  std::vector<double> start(own.values.begin(), own.values.begin() + n_static);
  const auto values_in = [&](const ModelFit& fit, const Candidate* c) -> std::vector<double> {
    std::size_t at = n_static;
    for (const Candidate* e : fit.effects) {
      const std::size_t n = e->params(model).size();
      if (e == c) return {fit.values.begin() + at, fit.values.begin() + at + n};
      at += n;
    }
    return {};
  };
  for (const Candidate* c : effects) {
    auto values = values_in(own, c);
    if (values.empty() && !c->linear_in_size(model)) values = values_in(other, c);
    if (values.empty())
      for (const auto& p : c->params(model)) values.push_back(p.nominal);
    if (!holds(own.effects, c) && c->linear_in_size(model)) values.front() = 0.0;
    start.insert(start.end(), values.begin(), values.end());
  }
  return start;
}

/// `model` fitted with `effects` from `start`, linear sizes with their sign free; the output
/// delay held at its start when `hold_delay`.
ModelFit comparison_fit(const DiagnosisModel& model, const Effects& effects,
                        const std::vector<double>& start, bool hold_delay,
                        const DiagnoseOptions& options) {
  FitSettings settings;
  settings.max_iterations = 2 * options.max_iterations;
  settings.threads = options.threads;
  settings.standard_errors = false;
  settings.signed_linear_sizes = true;
  if (hold_delay) {
    settings.fixed.assign(start.size(), false);
    settings.fixed[model.delay_index()] = true;
  }
  return fit_model(model, effects, start, settings);
}

/// The first parameter of `c` in `fit` on `model`.
double size_in(const DiagnosisModel& model, const ModelFit& fit, const Candidate* c) {
  std::size_t at = model.static_params().size();
  for (const Candidate* e : fit.effects) {
    if (e == c) return fit.values[at];
    at += e->params(model).size();
  }
  throw InputError("diagnose: internal: " + c->name() + " is not in the comparison fit");
}

/// Pairs of changes whose forces have one shape on today's drive: each gets the other's change
/// added, expressed in its own size.
void add_same_forces(const DiagnosisModel& model, const ModelFit& fit,
                     std::vector<EffectChange>& changes) {
  std::vector<std::vector<double>> shapes;
  for (const EffectChange& e : changes) shapes.push_back(unit_output_shape(model, fit, e.effect));
  for (std::size_t i = 0; i < changes.size(); ++i)
    for (std::size_t j = 0; j < changes.size(); ++j) {
      const double ii = shape_dot(shapes[i], shapes[i]), jj = shape_dot(shapes[j], shapes[j]);
      if (i == j || !(ii > 0.0) || !(jj > 0.0)) continue;
      const double ij = shape_dot(shapes[i], shapes[j]);
      const double correlation = ij / std::sqrt(ii * jj);
      if (std::abs(correlation) < kOneForce) continue;
      SameForce same;
      same.effect = changes[j].effect;
      same.correlation = correlation;
      same.combined_change = changes[i].change + changes[j].change * ij / ii;
      same.combined_derived = changes[i].effect->derived_params(model, {same.combined_change});
      changes[i].same_force.push_back(std::move(same));
    }
}

bool named_in(const Diagnosis& d, const Candidate* c) {
  return std::any_of(d.findings.begin(), d.findings.end(),
                     [c](const Finding& f) { return f.effect == c; });
}

/// " (moving_mass +153 kg)" for derived changes; "" for none.
std::string derived_text(const std::vector<DerivedParam>& derived) {
  std::string text;
  for (std::size_t j = 0; j < derived.size(); ++j)
    text += (j == 0 ? " (" : ", ") + derived[j].name + " " + (derived[j].value >= 0.0 ? "+" : "") +
            value_text(derived[j].value, derived[j].unit) + (j + 1 == derived.size() ? ")" : "");
  return text;
}

}  // namespace

ReferenceComparison compare_with_reference(const DiagnosisModel& today_model,
                                           const Diagnosis& today,
                                           const DiagnosisModel& reference_model,
                                           const Diagnosis& reference,
                                           const DiagnoseOptions& options) {
  ReferenceComparison out;
  out.recording = reference.recording;
  out.baseline_fit_percent = reference.baseline_fit_percent;
  for (const Finding& f : reference.findings) out.findings.push_back(f.effect->name());
  const Effects effects = comparison_effects(today_model, today, reference_model, reference);
  for (const DiagnosisModel* m : {&today_model, &reference_model})
    for (const Candidate* c : applicable_candidates(*m))
      if (c->linear_in_size(*m) && !holds(effects, c)) out.sized_on_one.push_back(c->name());
  const ModelFit before = comparison_fit(
      reference_model, effects,
      comparison_start(reference_model, reference.final_fit, today.final_fit, effects), false,
      options);
  auto start = comparison_start(today_model, today.final_fit, reference.final_fit, effects);
  start[today_model.delay_index()] = before.values[reference_model.delay_index()];
  const ModelFit now = comparison_fit(today_model, effects, start, true, options);
  out.reference_delay = before.values[reference_model.delay_index()];
  for (const Candidate* c : effects) {
    if (!c->linear_in_size(today_model)) continue;
    EffectChange e;
    e.effect = c;
    const auto own = c->params(today_model);
    e.param = own.front().name;
    e.unit = own.front().unit;
    e.today = size_in(today_model, now, c);
    e.named_today = named_in(today, c);
    e.reference = size_in(reference_model, before, c);
    e.named_reference = named_in(reference, c);
    e.change = e.today - e.reference;
    const auto derived_now = c->derived_params(today_model, {e.today});
    const auto derived_before = c->derived_params(reference_model, {e.reference});
    for (const DerivedParam& q : derived_now)
      for (const DerivedParam& r : derived_before)
        if (q.name == r.name) e.derived_change.push_back({q.name, q.value - r.value, q.unit});
    out.changes.push_back(std::move(e));
  }
  add_same_forces(today_model, now, out.changes);
  return out;
}

std::string change_text(const EffectChange& e) {
  std::string text = e.effect->name() + ": " + e.param + " " + value_text(e.today, e.unit) +
                     " today" + (e.named_today ? " (named)" : "") + ", " +
                     value_text(e.reference, e.unit) + " in the reference" +
                     (e.named_reference ? " (named)" : "") + " -> change " +
                     (e.change >= 0.0 ? "+" : "") + value_text(e.change, e.unit);
  text += derived_text(e.derived_change);
  for (const SameForce& same : e.same_force) {
    char correlation[32];
    std::snprintf(correlation, sizeof correlation, "%+.4f", same.correlation);
    text += "; one force with " + same.effect->name() + " on this drive (correlation " +
            correlation + "): together " + (same.combined_change >= 0.0 ? "+" : "") +
            value_text(same.combined_change, e.unit) + derived_text(same.combined_derived);
  }
  return text;
}

std::string reference_heading(const ReferenceComparison& r) {
  std::string named;
  for (const std::string& name : r.findings) named += (named.empty() ? "" : ", ") + name;
  return "change against the reference " + r.recording + " (same baseline: FIT " +
         percent_text(r.baseline_fit_percent) +
         " there, named there: " + (named.empty() ? "none" : named) +
         "; both fitted with what either named and every linear effect, sign free, today's "
         "output delay held at the reference's " +
         value_text(1e3 * r.reference_delay, "ms") + ")";
}

}  // namespace rheomag::diagnose
