// Why a candidate that lowered BIC is still not accepted, and the findings that fade.

#include "diagnose/diagnose_rejection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_nuisances.hpp"
#include "diagnose/diagnose_text.hpp"

namespace rheomag::diagnose {

namespace {

/// The output delay of `fit` [s] from the centre of the drive convention's range (held drives are
/// read half a sample late); 0 without a delay nuisance.
double output_delay_off_convention(const DiagnosisModel& model, const ModelFit& fit) {
  for (std::size_t j = 0; j < fit.layout.size(); ++j)
    if (fit.layout[j].name == "delay")
      return fit.values[j] - model.held_delay_shift() * model.sample_interval();
  return 0.0;
}

/// Why the lag that `effect`, the last effect of `fit`, adds is not told apart from the
/// recording's timing, continuing a sentence that names it ("" when it is, or adds no lag).
std::string timing_reason(const DiagnosisModel& model, const ModelFit& fit,
                          const Candidate* effect) {
  const double tau = effect->timing_lag(model, fit);
  if (!(tau > 0.0)) return "";
  const std::string sample = fmt(1e3 * model.sample_interval());
  // A time constant shorter than one sample interval cannot be told from the recording's own
  // timing (channel skew, held drives), which the delay nuisance already absorbs.
  if (tau < model.sample_interval())
    return " with a time constant of " + fmt(1e3 * tau) +
           " ms, shorter than one sample interval (" + sample +
           " ms): not told apart from the recording's timing; not accepted";
  // A lag the output delay takes back: with the delay leading the output by about the lag, the
  // two shift the output by under one sample and act as a smoothing of it, not as a lag.
  if (const double lead = -output_delay_off_convention(model, fit);
      tau - lead < model.sample_interval())
    return " with a time constant of " + fmt(1e3 * tau) + " ms and the output delay " +
           fmt(1e3 * lead) + " ms ahead of the drives: together they shift the output by under " +
           "one sample interval (" + sample +
           " ms), a smoothing of the recording's timing and not a lag; not accepted";
  return "";
}

}  // namespace

std::string rejection(const DiagnosisModel& model, const ModelFit& current, const ModelFit& fit,
                      const Candidate* effect, double delta_bic, const Evidence& evidence,
                      bool away, const DiagnoseOptions& options, double& share) {
  // Its size as fitted, so that what a recording carries of it below the bar is on record.
  const std::size_t own = fit.values.size() - effect->params(model).size();
  const std::string head = effect->name() + " (" + fit.layout[own].name + " " +
                           fmt(fit.values[own]) + " " + fit.layout[own].unit +
                           " as fitted) lowered BIC by " + fmt(delta_bic) +
                           (away ? " on the samples away from steps" : "");
  // What the candidate itself explains: the gain over the current model, but no more than the
  // error its fit gains back when the candidate alone is switched off (every other parameter
  // as fitted). A fit that only finishes converging the current model's own parameters (a
  // Coulomb force of a milli-newton beside a re-fitted compliance) is not credited with that.
  const auto on_set = [away](const TwoSse& e) { return away ? e.away : e.all; };
  const double sse_off =
      on_set(sse_switched_off(model, fit, fit.effects.size() - 1, evidence).second);
  const double sse_now =
      away ? two_sse(model.measured(), current.prediction, evidence).away : current.sse;
  const double sse_new = away ? two_sse(model.measured(), fit.prediction, evidence).away : fit.sse;
  const double floor_sse = away ? evidence.floor_away : evidence.floor_all;
  double explained_rms_in_sigma = 0.0;
  if (!material(sse_now, std::min(sse_now, sse_off) - sse_new, floor_sse, options, share,
                explained_rms_in_sigma)) {
    // Practical significance: a material share of the residual energy above the noise floor.
    if (share < options.min_share)
      return head + " but removed only " + fmt(100 * share, 2) +
             " % of the residual energy above the noise floor: not accepted";
    // Materiality against the noise: the output change it explains, in rms over the recording,
    // at least min_noise_multiple noise standard deviations (floor_sse = n sigma^2).
    return head + " but the output change it explains is only " + fmt(explained_rms_in_sigma, 2) +
           " noise standard deviations in rms (at least " + fmt(options.min_noise_multiple, 2) +
           " needed): below the noise, not accepted";
  }
  // A lag that the recording's timing could make (shorter than a sample, or taken back by the
  // output delay).
  if (auto why = timing_reason(model, fit, effect); !why.empty()) return head + why;
  // What the candidate itself finds implausible (e.g. a hysteresis loop inside the noise).
  if (auto why = effect->implausible(model, fit); !why.empty()) return head + why;
  // Identifiability: the effect's size parameter known to a relative standard error below
  // max_relative_se.
  const double rse =
      size_relative_se(model, fit, options.threads, away ? evidence.away : std::vector<bool>{});
  if (!(rse < options.max_relative_se))
    return head + " but its " + effect->params(model).front().name +
           " is not identified (relative standard error " +
           (std::isfinite(rse) ? fmt(100 * rse, 2) + " %" : std::string("unbounded")) +
           "): not accepted";
  return "";
}

ModelFit with_effect_last(const DiagnosisModel& model, const ModelFit& fit, std::size_t i) {
  std::size_t offset = model.static_params().size();
  for (std::size_t j = 0; j < i; ++j) offset += fit.effects[j]->params(model).size();
  const auto k = static_cast<std::ptrdiff_t>(fit.effects[i]->params(model).size());
  const auto at = static_cast<std::ptrdiff_t>(offset);
  ModelFit last = fit;
  auto to_end = [&](auto& v) {
    if (v.size() == fit.layout.size()) std::rotate(v.begin() + at, v.begin() + at + k, v.end());
  };
  to_end(last.layout);
  to_end(last.values);
  to_end(last.standard_errors);
  std::rotate(last.effects.begin() + static_cast<std::ptrdiff_t>(i),
              last.effects.begin() + static_cast<std::ptrdiff_t>(i) + 1, last.effects.end());
  return last;
}

void drop_faded_findings(const DiagnosisModel& model, ModelFit& fit, const Evidence& evidence,
                         const DiagnoseOptions& options, Diagnosis& d) {
  bool dropped = true;
  while (dropped && !fit.effects.empty()) {
    dropped = false;
    for (std::size_t i = 0; i < fit.effects.size(); ++i) {
      const Candidate* e = fit.effects[i];
      // What speaks against it in its jointly re-fitted parameters: a lag the re-fitted output
      // delay takes back, or what the candidate finds implausible (e.g. a loop that the re-fit
      // closed to the top of its reversible range).
      const ModelFit last = with_effect_last(model, fit, i);
      std::string why = timing_reason(model, last, e);
      if (why.empty()) why = e->implausible(model, last);
      const auto [without, sse_off] = sse_switched_off(model, fit, i, evidence);
      if (!std::isfinite(sse_off.all)) continue;
      if (why.empty()) {
        if (fit.effects.size() < 2) continue;
        const TwoSse with{fit.sse, two_sse(model.measured(), fit.prediction, evidence).away};
        double share = 0.0, share_away = 0.0, rms = 0.0;
        if (material(sse_off.all, sse_off.all - with.all, evidence.floor_all, options, share,
                     rms) ||
            (!evidence.away.empty() && material(sse_off.away, sse_off.away - with.away,
                                                evidence.floor_away, options, share_away, rms)))
          continue;
        d.notes.push_back(e->name() +
                          " was accepted in forward selection but in the joint "
                          "re-fit it explains only " +
                          fmt(100 * std::max(share, share_away), 2) +
                          " % of the residual energy above the noise floor: not reported");
      } else {
        d.notes.push_back(e->name() + " was accepted in forward selection but in the joint re-fit" +
                          why.substr(0, why.rfind("; not accepted")) + ": not reported");
      }
      d.findings.erase(std::remove_if(d.findings.begin(), d.findings.end(),
                                      [e](const Finding& f) { return f.effect == e; }),
                       d.findings.end());
      // The model without it, its parameters as fitted (standard errors from one evaluation).
      FitSettings s;
      s.max_iterations = 0;
      s.threads = options.threads;
      fit = fit_model(model, without.effects, without.values, s);
      dropped = true;
      break;
    }
  }
}

double size_relative_se(const DiagnosisModel& model, const ModelFit& fit, int threads,
                        const std::vector<bool>& mask) {
  FitSettings s;
  s.mask = mask;
  s.max_iterations = 0;
  s.threads = threads;
  s.fixed = held_in_candidates(model, fit.effects, fit.values);
  const auto f = fit_model(model, fit.effects, fit.values, s);
  const std::size_t j = f.layout.size() - f.effects.back()->params(model).size();
  const double v = std::abs(f.values[j]);
  return v > 0.0 ? f.standard_errors[j] / v : std::numeric_limits<double>::infinity();
}

}  // namespace rheomag::diagnose
