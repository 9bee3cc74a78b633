// The noise floor of a residual and what one effect of a model explains.

#include "diagnose/diagnose_evidence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_noise.hpp"

namespace rheomag::diagnose {

Evidence evidence_of(const std::vector<double>& baseline_prediction, double sigma) {
  Evidence e;
  e.away = away_from_steps(baseline_prediction);
  const auto n = static_cast<double>(baseline_prediction.size());
  const auto n_away =
      e.away.empty() ? n : static_cast<double>(std::count(e.away.begin(), e.away.end(), true));
  e.floor_all = n * sigma * sigma;
  e.floor_away = n_away * sigma * sigma;
  return e;
}

TwoSse two_sse(const std::vector<double>& measured, const std::vector<double>& prediction,
               const Evidence& e) {
  const double all = masked_sse(measured, prediction, {});
  return {all, e.away.empty() ? all : masked_sse(measured, prediction, e.away)};
}

std::pair<EffectSet, TwoSse> sse_switched_off(const DiagnosisModel& model, const ModelFit& fit,
                                              std::size_t i, const Evidence& evidence) {
  std::size_t offset = model.static_params().size();
  for (std::size_t j = 0; j < i; ++j) offset += fit.effects[j]->params(model).size();
  const std::size_t k = fit.effects[i]->params(model).size();
  EffectSet without{fit.effects, fit.values};
  without.effects.erase(without.effects.begin() + static_cast<std::ptrdiff_t>(i));
  without.values.erase(without.values.begin() + static_cast<std::ptrdiff_t>(offset),
                       without.values.begin() + static_cast<std::ptrdiff_t>(offset + k));
  const double inf = std::numeric_limits<double>::infinity();
  TwoSse sse{inf, inf};
  try {
    sse = two_sse(model.measured(), model.predict(without.effects, without.values), evidence);
  } catch (const ConvergenceError&) {
  }
  return {std::move(without), sse};
}

bool material(double sse, double gain, double floor_sse, const DiagnoseOptions& options,
              double& share, double& rms_in_sigma) {
  const double excess = sse - floor_sse;
  share = excess > 0.0 ? gain / excess : 0.0;
  rms_in_sigma = floor_sse > 0.0 ? std::sqrt(std::max(gain, 0.0) / floor_sse) : 1e300;
  return share >= options.min_share && rms_in_sigma >= options.min_noise_multiple;
}

}  // namespace rheomag::diagnose
