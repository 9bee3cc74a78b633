// Forward selection of candidate physics on top of the calibrated baseline.

#include "diagnose/diagnose_selection.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include "core/error.hpp"
#include "diagnose/candidate.hpp"
#include "diagnose/candidate_registry.hpp"
#include "diagnose/diagnose_findings.hpp"
#include "diagnose/diagnose_heldout.hpp"
#include "diagnose/diagnose_nuisances.hpp"
#include "diagnose/diagnose_rejection.hpp"
#include "diagnose/diagnose_signed_size.hpp"
#include "lumped/metrics.hpp"

namespace rheomag::diagnose {

namespace {

double bic(double sse, std::size_t n, std::size_t k) {
  const double nn = static_cast<double>(n);
  return nn * std::log(std::max(sse, 1e-300) / nn) + static_cast<double>(k) * std::log(nn);
}

/// True when `f` has the candidate called `name`.
bool has_effect(const ModelFit& f, const std::string& name) {
  return std::any_of(f.effects.begin(), f.effects.end(),
                     [&](const Candidate* e) { return e->name() == name; });
}

/// The score of candidate `c` fitted at `step` as the last effect of `f`, with its own
/// parameters (the tail of `f`'s layout).
CandidateScore fitted_score(const DiagnosisModel& model, const Candidate* c, int step,
                            const std::vector<double>& measured, const ModelFit& f,
                            double delta_bic) {
  CandidateScore score;
  score.effect = c;
  score.step = step;
  score.fit_percent = lumped::fit_percent(measured, f.prediction);
  score.delta_bic = delta_bic;
  const std::size_t own = c->params(model).size();
  for (std::size_t j = f.values.size() - std::min(own, f.values.size()); j < f.values.size(); ++j) {
    score.param_names.push_back(f.layout[j].name);
    score.param_units.push_back(f.layout[j].unit);
    score.params.push_back(f.values[j]);
  }
  return score;
}

/// Whether candidate `c` is tried again at `step` (> 0). A candidate fitted at the first step is
/// retried at every step unless it made the fit clearly worse alone (BIC up by more than
/// `margin`): masked by a larger effect, it still gets its second chance. A candidate screened
/// out at the first step (no decade of its parameter helped the bare baseline), or fitted there
/// and clearly worse, is tried once more, at the step after the first accepted effect, and not
/// after it: an effect can be invisible beside the one it sits next to (a Coulomb step beside a
/// chamber compliance, a magnetic loop beside air, that is not yet in) and show once that one is
/// in; one that shows only after two others is not looked for.
bool worth_retrying(const std::vector<CandidateScore>& scores, const Candidate* c, int step,
                    double margin) {
  for (const auto& s : scores)
    if (s.step == 0 && s.effect == c)
      return s.screened || s.delta_bic <= -margin ? step == 1 : true;
  return false;
}

/// Candidates whose output fits tie (within 5 % of the best's improvement) are told apart by
/// the measured coil current when the recording has one that the model does not take as input:
/// coil inductance delays that current, field and fluid lags do not. Returns the tied candidates
/// that the current rules out (their current error at least twice the best's).
template <class Tried>
std::vector<const Candidate*> prefer_by_measured_current(const DiagnosisModel& model,
                                                         std::vector<Tried>& tried) {
  const auto& rec = model.recording();
  if (tried.size() < 2 || model.output_column() == "current" || !rec.columns.count("current") ||
      std::find(rec.meta.drive.begin(), rec.meta.drive.end(), "current") != rec.meta.drive.end())
    return {};
  const double best = tried.front().fit.sse;
  const double spread = 0.05 * std::abs(best);
  std::size_t tied = 1;
  while (tied < tried.size() && tried[tied].fit.sse - best < spread) ++tied;
  if (tied < 2) return {};
  const auto& measured = rec.column("current");
  std::vector<double> current_sse(tied);
  for (std::size_t i = 0; i < tied; ++i) {
    try {
      const auto c = model.predict_column(tried[i].fit.effects, tried[i].fit.values, "current");
      current_sse[i] = masked_sse(measured, c, {});
    } catch (const std::exception&) {
      current_sse[i] = std::numeric_limits<double>::infinity();
    }
  }
  const auto best_i = static_cast<std::size_t>(
      std::min_element(current_sse.begin(), current_sse.end()) - current_sse.begin());
  std::vector<const Candidate*> ruled_out;
  for (std::size_t i = 0; i < tied; ++i)
    if (current_sse[i] > 2.0 * current_sse[best_i]) ruled_out.push_back(tried[i].effect);
  if (current_sse[best_i] < 0.5 * current_sse[0]) std::swap(tried[0], tried[best_i]);
  return ruled_out;
}

/// Most candidates tried for acceptance at one forward step (each costs a held-out check).
constexpr std::size_t kMaxTries = 3;

}  // namespace

ModelFit forward_select(const DiagnosisModel& model, ModelFit current, const Evidence& evidence,
                        const DiagnoseOptions& options, Diagnosis& d, Clock& clock) {
  const auto& y = model.measured();
  const std::size_t n = y.size();
  FitSettings settings;
  settings.max_iterations = options.max_iterations;
  settings.threads = options.threads;
  settings.standard_errors = false;  // only the final model's are reported
  // BIC on the samples away from steps (the residual at a step is its unrecorded timing, which
  // is not Gaussian noise about the model: it can swamp a slow effect's gain in the likelihood).
  const std::size_t n_away =
      evidence.away.empty()
          ? n
          : static_cast<std::size_t>(std::count(evidence.away.begin(), evidence.away.end(), true));
  auto delta_bic_away = [&](const ModelFit& before, const ModelFit& after) {
    return bic(two_sse(y, before.prediction, evidence).away, n_away, before.values.size()) -
           bic(two_sse(y, after.prediction, evidence).away, n_away, after.values.size());
  };
  // Held-out error of `current` on every sample and away from steps, once known (< 0: not yet).
  TwoSse held_current{-1.0, -1.0};
  const auto candidates = applicable_candidates(model);
  for (int step = 0; step < options.max_effects; ++step) {
    struct Tried {
      const Candidate* effect;
      ModelFit fit;
      double delta_bic;
      bool delay_freed =
          false;  ///< fitted with the output delay the baseline put at its bound free
    };
    std::vector<Tried> tried;
    // The current model with its best output delay (one simulation): each candidate is fitted
    // with the delay free, so the gain it is credited with must not be the delay's.
    if (!held_in_candidates(model, current.effects, current.values)[model.delay_index()])
      polish_delay(model, current);
    if (step > 0) recalibrate_nuisances(model, current, settings);
    const double bic_now = bic(current.sse, n, current.values.size());
    const bool first_step = step == 0;
    const auto step_started = std::chrono::steady_clock::now();
    double candidates_done = 0.0;
    // Each candidate's result, as "k of at most N" of this step (N counts those skipped).
    const auto report = [&](const Candidate* c, const std::string& detail) {
      candidates_done += 1.0;
      clock.report_since({"step " + std::to_string(step + 1) + " " + c->name(), candidates_done,
                          static_cast<double>(candidates.size()), 0.0, detail, true},
                         step_started);
    };
    for (const Candidate* c : candidates) {
      if (std::find(current.effects.begin(), current.effects.end(), c) != current.effects.end())
        continue;
      // After the first step, candidates that made the fit clearly worse are not retried.
      if (!first_step && !worth_retrying(d.candidates, c, step, options.bic_margin)) continue;
      // A candidate that is the same block in the rig model as another (e.g. eddy currents and
      // MR response time, one first-order lag): while that one is not in yet, this one's fit is
      // that one's under another name.
      if (const std::string twin_name = c->same_block_as();
          !twin_name.empty() && !has_effect(current, twin_name)) {
        auto twin = std::find_if(tried.begin(), tried.end(),
                                 [&](const auto& t) { return t.effect->name() == twin_name; });
        if (twin != tried.end()) {
          d.candidates.push_back(fitted_score(model, c, step, y, twin->fit, twin->delta_bic));
          tried.push_back({c, twin->fit, twin->delta_bic, twin->delay_freed});
          tried.back().fit.effects.back() = c;
          continue;
        }
      }
      auto effects = current.effects;
      effects.push_back(c);
      auto s = current.values;
      for (const auto& p : c->params(model)) s.push_back(p.nominal);
      try {
        const auto started = std::chrono::steady_clock::now();
        double grid_sse = 0.0;
        const bool scan_delay = !held_in_candidates(model, effects, s)[model.delay_index()];
        // Starts measured on the recording (e.g. the inertance at the residual's ringing) beside
        // the decade grid: the error can be multimodal in the candidate's size.
        const auto starts =
            options.ringing_start ? c->measured_starts(model, current) : std::vector<double>{};
        const auto nominal = s;
        s = grid_start(model, effects, s, &grid_sse, options.threads, scan_delay, starts);
        // Screening: a candidate that lowers the error at no decade of its parameter (the
        // others held at the current fit) is scored there and not fitted.
        if (!(grid_sse < current.sse)) {
          const double db = bic_now - bic(grid_sse, n, s.size());
          CandidateScore screened;
          screened.effect = c;
          screened.step = step;
          screened.delta_bic = db;
          screened.screened = true;
          if (first_step) add_signed_size(model, current, settings, screened);
          d.candidates.push_back(std::move(screened));
          report(c, "screened out (no decade of its parameter helps)");
          continue;
        }
        auto candidate_settings = settings;
        candidate_settings.fixed = held_in_candidates(model, effects, current.values);
        auto f = fit_model(model, effects, s, candidate_settings);
        const bool delay_freed =
            !scan_delay && keep_better_with_free_delay(model, effects, nominal, candidate_settings,
                                                       starts, options.threads, f);
        const double db = bic_now - bic(f.sse, n, f.values.size());
        report(c, "dBIC " + num(db) + " in " + num(Clock::since(started)) + " s");
        d.candidates.push_back(fitted_score(model, c, step, y, f, db));
        if (first_step) add_signed_size(model, current, settings, d.candidates.back());
        tried.push_back({c, std::move(f), db, delay_freed});
      } catch (const ConvergenceError&) {
        d.notes.push_back("candidate " + c->name() + " could not be simulated at step " +
                          std::to_string(step + 1));
      }
    }
    clock.stage("step " + std::to_string(step + 1) + " candidates");
    if (tried.empty()) break;
    std::stable_sort(tried.begin(), tried.end(),
                     [](const Tried& a, const Tried& b) { return a.delta_bic > b.delta_bic; });
    const auto ruled_out = prefer_by_measured_current(model, tried);
    // The best candidate that passes every test is accepted; one that fails is noted and the
    // next best (by BIC) is tried, up to kMaxTries of them.
    const int cv_iterations = std::max(options.max_iterations / 3, 5);
    std::vector<const Candidate*> rejected;
    double gain = 0.0, share = 0.0;
    TwoSse held_new;
    std::size_t accepted = tried.size();
    for (std::size_t i = 0; i < tried.size() && i < kMaxTries; ++i) {
      const auto& c = tried[i];
      // Every test is passed on one sample set: every sample, or those away from steps. The
      // second set is tried only when the first does not already accept the candidate (each
      // try costs a Jacobian and, past the tests, four fold fits).
      auto held_gain = [&](bool away, double& now, double& with) {
        const auto& keep = away ? evidence.away : std::vector<bool>{};
        if (now < 0.0)
          now = heldout_sse(model, current, options.blocks, cv_iterations, options.threads, keep);
        with = heldout_sse(model, c.fit, options.blocks, cv_iterations, options.threads, keep);
        return now > 0.0 ? 1.0 - with / now : 0.0;
      };
      held_new = {-1.0, -1.0};
      std::string why;
      bool tested = false;  // passed the tests before the held-out check on some set
      gain = -std::numeric_limits<double>::infinity();
      if (c.delta_bic > options.bic_margin) {
        why = rejection(model, current, c.fit, c.effect, c.delta_bic, evidence, false, options,
                        share);
        if (why.empty()) {
          tested = true;
          gain = held_gain(false, held_current.all, held_new.all);
        }
      }
      if (gain < options.heldout_margin && !evidence.away.empty()) {
        const double db_away = delta_bic_away(current, c.fit);
        double share_away = 0.0;
        const auto why_away = db_away > options.bic_margin
                                  ? rejection(model, current, c.fit, c.effect, db_away, evidence,
                                              true, options, share_away)
                                  : std::string("-");
        if (why_away.empty()) {
          tested = true;
          const double gain_away = held_gain(true, held_current.away, held_new.away);
          if (gain_away > gain) gain = gain_away, share = share_away;
        } else if (why.empty() && !tested && why_away != "-") {
          why = why_away;
        }
      }
      if (!tested) {
        if (!why.empty()) d.notes.push_back(why);
        if (!why.empty()) rejected.push_back(c.effect);
        continue;
      }
      clock.stage("held-out check of " + c.effect->name());
      if (gain < options.heldout_margin) {
        d.notes.push_back(c.effect->name() + " lowered BIC by " + fmt(c.delta_bic) +
                          " but cut the held-out error by only " + fmt(100 * gain, 2) +
                          " %: not accepted");
        rejected.push_back(c.effect);
        continue;
      }
      accepted = i;
      break;
    }
    if (accepted == tried.size()) break;
    std::swap(tried[0], tried[accepted]);
    const auto& best = tried.front();
    Finding f;
    f.effect = best.effect;
    f.step = step;
    f.fit_percent = lumped::fit_percent(y, best.fit.prediction);
    f.delta_bic = best.delta_bic;
    f.heldout_gain = gain;
    f.share = share;
    const double reduction = current.sse - best.fit.sse;
    for (std::size_t i = 1; i < tried.size(); ++i)
      if (std::find(rejected.begin(), rejected.end(), tried[i].effect) != rejected.end()) {
        continue;  // failed a test of its own: not an equally good explanation
      } else if (std::find(ruled_out.begin(), ruled_out.end(), tried[i].effect) !=
                     ruled_out.end() &&
                 tried[i].effect != best.effect) {
        f.ruled_out_by_current.push_back(tried[i].effect);
      } else if (tried[i].fit.sse - best.fit.sse < 0.05 * reduction) {
        f.ambiguous_with.push_back(tried[i].effect);
        // One measurement per distinct way of telling a tied candidate apart.
        const auto how = separating_measurement(*best.effect, *tried[i].effect);
        if (f.separating_measurement.find(how) == std::string::npos)
          f.separating_measurement += (f.separating_measurement.empty() ? "" : "; ") + how;
      }
    d.findings.push_back(std::move(f));
    if (best.delay_freed)
      d.notes.push_back(best.effect->name() +
                        " was fitted with the output delay free: the baseline had put the delay "
                        "at its bound, and held there the fit was worse (the effect may be what "
                        "pushed it there)");
    current = best.fit;
    held_current = held_new;
  }

  return current;
}

}  // namespace rheomag::diagnose
