// A candidate's size against the baseline with its sign free.

#include "diagnose/diagnose_signed_size.hpp"

#include "core/error.hpp"
#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_nuisances.hpp"

namespace rheomag::diagnose {

namespace {

/// The size of `effects.back()` fitted with its sign free from `start`, with the delay also
/// freed when `settings` holds it; the lower-error fit.
ModelFit signed_fit(const DiagnosisModel& model, const std::vector<const Candidate*>& effects,
                    const std::vector<double>& start, FitSettings settings) {
  settings.signed_last_size = true;
  ModelFit fit = fit_model(model, effects, start, settings);
  const std::size_t delay = model.delay_index();
  if (delay < settings.fixed.size() && settings.fixed[delay]) {
    settings.fixed[delay] = false;
    try {
      ModelFit free = fit_model(model, effects, start, settings);
      if (free.sse < fit.sse) fit = std::move(free);
    } catch (const ConvergenceError&) {
      // the held fit stands
    }
  }
  return fit;
}

}  // namespace

void add_signed_size(const DiagnosisModel& model, const ModelFit& current,
                     const FitSettings& settings, CandidateScore& score) {
  const Candidate* c = score.effect;
  if (!c->linear_in_size(model)) return;
  const auto own = c->params(model);
  const ParamDef& size = own.front();
  if (score.param_names.empty())  // screened: named here for the signed size
    for (const auto& p : own)
      score.param_names.push_back(p.name), score.param_units.push_back(p.unit);
  if (!score.screened && !score.params.empty() && score.params.front() > 1.01 * size.lower) {
    score.signed_params = score.params;
  } else {
    auto effects = current.effects;
    effects.push_back(c);
    auto start = current.values;
    start.push_back(0.0);
    auto s = settings;
    s.fixed = held_in_candidates(model, effects, current.values);
    try {
      const ModelFit fit = signed_fit(model, effects, start, s);
      score.signed_params.assign(fit.values.end() - 1, fit.values.end());
    } catch (const ConvergenceError&) {
      return;
    }
  }
  score.signed_derived = c->derived_params(model, score.signed_params);
}

}  // namespace rheomag::diagnose
