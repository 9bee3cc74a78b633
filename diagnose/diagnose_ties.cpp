// Ties decided again in the joint model (diagnose_ties.hpp).

#include "diagnose/diagnose_ties.hpp"

#include <algorithm>
#include <cmath>

#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_rejection.hpp"
#include "diagnose/diagnose_text.hpp"

namespace rheomag::diagnose {

namespace {

/// The score of candidate `c` at selection step `step` (nullptr if it was not tried there).
const CandidateScore* score_at(const Diagnosis& d, const Candidate* c, int step) {
  for (const CandidateScore& s : d.candidates)
    if (s.effect == c && s.step == step) return &s;
  return nullptr;
}

/// The start of `fit`'s model with effect i replaced by `other` at `other_params`.
std::vector<double> swapped_start(const DiagnosisModel& model, const ModelFit& fit, std::size_t i,
                                  const std::vector<double>& other_params) {
  std::size_t offset = model.static_params().size();
  std::vector<double> start(fit.values.begin(), fit.values.begin() + offset);
  for (std::size_t j = 0; j < fit.effects.size(); ++j) {
    const std::size_t k = fit.effects[j]->params(model).size();
    if (j == i)
      start.insert(start.end(), other_params.begin(), other_params.end());
    else
      start.insert(start.end(), fit.values.begin() + offset, fit.values.begin() + offset + k);
    offset += k;
  }
  return start;
}

}  // namespace

void revisit_ties(const DiagnosisModel& model, ModelFit& fit, const FitSettings& settings,
                  double bic_margin, Diagnosis& d) {
  const double n = static_cast<double>(fit.samples);
  if (!(n > 0.0) || !(fit.sse > 0.0) || !std::isfinite(fit.sse)) return;
  for (std::size_t i = 0; i < d.findings.size() && i < fit.effects.size(); ++i) {
    Finding& f = d.findings[i];
    if (fit.effects[i] != f.effect) return;  // the joint model's order is the findings' order
    // A tie at the last step was judged with every other finding in already.
    const bool later = std::any_of(d.findings.begin(), d.findings.end(),
                                   [&f](const Finding& g) { return g.step > f.step; });
    if (!later) continue;
    const CandidateScore* own = score_at(d, f.effect, f.step);
    for (std::size_t a = 0; a < f.ambiguous_with.size(); ++a) {
      const Candidate* other = f.ambiguous_with[a];
      if (std::find(fit.effects.begin(), fit.effects.end(), other) != fit.effects.end()) continue;
      const CandidateScore* theirs = score_at(d, other, f.step);
      if (!theirs || theirs->params.size() != other->params(model).size()) continue;
      if (own && theirs->fit_percent == own->fit_percent) continue;  // one model, two names
      std::vector<const Candidate*> effects = fit.effects;
      effects[i] = other;
      ModelFit swapped =
          fit_model(model, effects, swapped_start(model, fit, i, theirs->params), settings);
      if (!std::isfinite(swapped.sse) || !(swapped.sse > 0.0)) continue;
      const double extra_params = static_cast<double>(other->params(model).size()) -
                                  static_cast<double>(f.effect->params(model).size());
      const double delta_bic = n * std::log(fit.sse / swapped.sse) - extra_params * std::log(n);
      if (!(delta_bic > bic_margin)) continue;
      const std::string why = other->implausible(model, with_effect_last(model, swapped, i));
      if (!why.empty()) continue;
      d.notes.push_back(f.effect->name() + " and " + other->name() + " tied at selection step " +
                        std::to_string(f.step + 1) + "; with every finding in, " + other->name() +
                        " fits better (BIC " + fmt(delta_bic) + " lower): named instead");
      f.ambiguous_with[a] = f.effect;
      f.effect = other;
      fit = std::move(swapped);
      break;
    }
  }
}

}  // namespace rheomag::diagnose
