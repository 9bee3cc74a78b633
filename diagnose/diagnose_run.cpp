// Forward selection of missing physics on top of the calibrated baseline.

#include "diagnose/diagnose_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <thread>
#include <utility>

#include "core/error.hpp"
#include "diagnose/diagnose_noise.hpp"
#include "diagnose/diagnose_ringing.hpp"
#include "lumped/metrics.hpp"
#include "lumped/recording_excerpt.hpp"

namespace rheomag::diagnose {

namespace {

constexpr std::size_t kMinSamples = 100;

double bic(double sse, std::size_t n, std::size_t k) {
  const double nn = static_cast<double>(n);
  return nn * std::log(std::max(sse, 1e-300) / nn) + static_cast<double>(k) * std::log(nn);
}

double fit_percent_of(const std::vector<double>& y, const std::vector<double>& yhat) {
  return lumped::fit_percent(y, yhat);
}

bool has_effect(const ModelFit& f, Effect e) {
  return std::find(f.effects.begin(), f.effects.end(), e) != f.effects.end();
}

/// Whether candidate `c` is tried again at `step` (> 0). A candidate fitted at the first step is
/// retried unless it made the fit clearly worse alone (BIC up by more than `margin`): masked by
/// a larger effect, it still gets its second chance. A candidate screened out at the first step
/// (no decade of its parameter helped the bare baseline) is re-screened once, at the step after
/// the first accepted effect, and not after it: an effect can be invisible beside the one it
/// sits next to (a Coulomb step beside a chamber compliance that is not yet in) and show once
/// that one is in; one that shows only after two others is not looked for.
bool worth_retrying(const std::vector<CandidateScore>& scores, Effect c, int step, double margin) {
  for (const auto& s : scores)
    if (s.step == 0 && s.effect == c) return s.screened ? step == 1 : s.delta_bic > -margin;
  return false;
}

/// Candidates whose output fits tie (within 5 % of the best's improvement) are told apart by
/// the measured coil current when the recording has one that the model does not take as input:
/// coil inductance delays that current, field and fluid lags do not. Returns the tied candidates
/// that the current rules out (their current error at least twice the best's).
template <class Tried>
std::vector<Effect> prefer_by_measured_current(const DiagnosisModel& model,
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
  std::vector<Effect> ruled_out;
  for (std::size_t i = 0; i < tied; ++i)
    if (current_sse[i] > 2.0 * current_sse[best_i]) ruled_out.push_back(tried[i].effect);
  if (current_sse[best_i] < 0.5 * current_sse[0]) std::swap(tried[0], tried[best_i]);
  return ruled_out;
}

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

/// The baseline's nuisances held (true) in the layout of `effects`: while candidates are
/// fitted and screened, the recording's timing and pre-yield smoothness stay as calibrated; the
/// held-out folds and the final joint re-fit free them (a fold fitted with them held can land
/// in another optimum and score a real effect as useless).
std::vector<bool> nuisances_held(const DiagnosisModel& model, const std::vector<Effect>& effects) {
  std::vector<bool> held(model.layout(effects).size(), false);
  const std::size_t n_static = model.static_params().size();
  for (std::size_t j = n_static - model.nuisance_count(); j < n_static; ++j) held[j] = true;
  return held;
}

/// Nuisances held while a candidate is screened and fitted: the pre-yield smoothness always;
/// the output delay only when the baseline put it at its bound (it was free to absorb a
/// candidate's phase, e.g. an inertia's lead or a compliance's lag, and is re-fitted with each
/// candidate so that the comparison is between two models each with its best delay; at a bound
/// it would make every step project onto the bound).
std::vector<bool> held_in_candidates(const DiagnosisModel& model,
                                     const std::vector<Effect>& effects,
                                     const std::vector<double>& values) {
  auto held = nuisances_held(model, effects);
  const auto layout = model.static_params();
  for (std::size_t j = model.delay_index(); j < layout.size(); ++j) {
    const auto& p = layout[j];
    const double v = values[j];
    const bool at_bound = p.log_scale ? v <= p.lower * 1.001 || v >= p.upper / 1.001
                                      : std::abs(v - p.lower) < 5e-4 * (p.upper - p.lower) ||
                                            std::abs(v - p.upper) < 5e-4 * (p.upper - p.lower);
    if (!at_bound) held[j] = false;
  }
  return held;
}

/// Re-calibrates the nuisances of `fit` that are not at a bound with everything else held (after
/// an accepted effect the pre-yield smoothing and delay it was compared with may no longer be
/// the best, and the next candidate would be credited with their gain).
void recalibrate_nuisances(const DiagnosisModel& model, ModelFit& fit, const FitSettings& base) {
  auto free = held_in_candidates(model, fit.effects, fit.values);
  bool any = false;
  std::vector<bool> fixed(fit.values.size(), true);
  for (std::size_t j = model.delay_index(); j < model.static_params().size(); ++j)
    if (!free[j]) fixed[j] = false, any = true;
  if (!any) return;
  auto s = base;
  s.fixed = fixed;
  auto f = fit_model(model, fit.effects, fit.values, s);
  if (f.sse < fit.sse) fit = std::move(f);
}

/// Sets `fit`'s output delay to its best value for the rest of its parameters (no refit).
void polish_delay(const DiagnosisModel& model, ModelFit& fit) {
  const std::size_t j = model.delay_index();
  auto values = fit.values;
  values[j] = 0.0;
  double sse = 0.0;
  const auto undelayed = model.predict(fit.effects, values);
  const double delay = model.best_delay(undelayed, values, sse);
  if (!(sse < fit.sse)) return;
  fit.values[j] = delay;
  fit.sse = sse;
  fit.prediction = model.delayed(undelayed, fit.values);
}

std::vector<bool> block_mask(std::size_t n, int blocks, bool even) {
  std::vector<bool> mask(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto b = static_cast<int>(k * static_cast<std::size_t>(blocks) / n);
    mask[k] = (b % 2 == 0) == even;
  }
  return mask;
}

/// What no candidate can explain in a model's residual, on two sets of samples: every sample,
/// and the samples away from the steps of the baseline's prediction (away_from_steps), whose
/// values depend on the unrecorded sub-sample instant of a drive step. The white noise floor
/// n sigma^2 is counted on each set.
struct Evidence {
  std::vector<bool> away;   ///< samples away from steps (empty: every sample)
  double floor_all = 0.0;   ///< n sigma^2 on every sample
  double floor_away = 0.0;  ///< the same on the samples away from steps
};

/// The Evidence of a baseline prediction whose residual has white noise of deviation `sigma`.
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

/// A squared error on every sample and on the samples away from steps (Evidence).
struct TwoSse {
  double all = 0.0, away = 0.0;
};

/// The squared error of `prediction` against `measured` on both sample sets of `e`.
TwoSse two_sse(const std::vector<double>& measured, const std::vector<double>& prediction,
               const Evidence& e) {
  const double all = masked_sse(measured, prediction, {});
  return {all, e.away.empty() ? all : masked_sse(measured, prediction, e.away)};
}

/// Held-out squared error: fit on even blocks, score on odd, and the other way round (the two
/// folds on two threads when `threads` > 1); only on the samples of `keep` when it is not empty
/// (the samples away from steps: a fold fitted to the steps' residual moves the delay and the
/// candidate with the few steps the fold holds).
double heldout_sse(const DiagnosisModel& model, const ModelFit& full, int blocks, int iterations,
                   int threads, const std::vector<bool>& keep) {
  double fold_sse[2] = {0.0, 0.0};
  std::exception_ptr failure[2];
  auto fold = [&](int k) {
    try {
      FitSettings s;
      s.mask = block_mask(model.measured().size(), blocks, k == 0);
      auto other = s.mask;
      other.flip();
      for (std::size_t i = 0; i < keep.size(); ++i) {
        s.mask[i] = s.mask[i] && keep[i];
        other[i] = other[i] && keep[i];
      }
      s.max_iterations = iterations;
      s.threads = threads > 1 ? std::max(threads / 2, 1) : 1;
      s.standard_errors = false;
      s.projected_line_search = true;
      const auto f = fit_model(model, full.effects, full.values, s);
      fold_sse[k] = masked_sse(model.measured(), f.prediction, other);
    } catch (...) {
      failure[k] = std::current_exception();
    }
  };
  if (threads > 1) {
    std::thread second(fold, 1);
    fold(0);
    second.join();
  } else {
    fold(0);
    fold(1);
  }
  for (const auto& e : failure)
    if (e) std::rethrow_exception(e);
  return fold_sse[0] + fold_sse[1];
}

std::string num(double v) {
  std::ostringstream text;
  text << v;
  return text.str();
}

std::string fmt(double v, int digits = 3) {
  std::ostringstream o;
  o.precision(digits);
  o << v;
  return o.str();
}

double regime_share(const std::vector<MismatchWindow>& windows, const std::string& regime) {
  double s = 0.0;
  for (const auto& w : windows)
    if (w.regime == regime) s += w.share;
  return s;
}

std::string evidence_for(Effect e, const Diagnosis& d, const ModelFit& fit) {
  std::ostringstream o;
  const auto& st = d.baseline_stats;
  const double lag_ms = 1e3 * st.output_lag;
  auto value = [&](const std::string& name) {
    for (std::size_t j = 0; j < fit.layout.size(); ++j)
      if (fit.layout[j].name == name) return fit.values[j];
    return 0.0;
  };
  switch (e) {
    case Effect::compressibility:
      o << "the output lags the baseline by " << fmt(lag_ms) << " ms; "
        << fmt(100 * regime_share(d.mismatch, "flow reversal"), 2)
        << " % of the residual energy sits at flow reversals, where a chamber with "
        << fmt(value("air_volume")) << " m^3 of air per chamber must be compressed before "
        << "pressure can build";
      break;
    case Effect::fluid_inertia:
      o << "the residual follows the piston acceleration (";
      if (lag_ms < 0.0)
        o << "the output leads the baseline by " << fmt(-lag_ms) << " ms";
      else
        o << "the output lags the baseline by " << fmt(lag_ms)
          << " ms overall, which inertia alone would not do";
      o << "); an inertance of " << fmt(value("inertance")) << " Pa s^2/m^3 explains it";
      break;
    case Effect::eddy_currents:
    case Effect::mr_response_time: {
      const double edges = regime_share(d.mismatch, "current rising edge") +
                           regime_share(d.mismatch, "current falling edge");
      o << "the output lags the baseline by " << fmt(lag_ms) << " ms"
        << (edges >= 0.5 ? ", mostly at current edges (" : " (") << fmt(100 * edges, 2)
        << " % of the residual energy in rising/falling-edge windows); a first-order lag of "
        << fmt(1e3 * value("time_constant")) << " ms between current and yield stress removes it";
      break;
    }
    case Effect::coil_inductance: {
      // The coil resistance: fitted on a coil bench, else as the sidecar states it.
      double resistance = value("coil_resistance");
      for (const BaselineItem& item : d.includes)
        if (resistance <= 0.0 && item.name == "coil_resistance") resistance = item.value;
      o << "the response lags the coil voltage at its edges (output " << fmt(lag_ms)
        << " ms behind the baseline); an inductance of " << fmt(value("inductance")) << " H";
      if (resistance > 0.0)
        o << " (L/R = " << fmt(1e3 * value("inductance") / resistance) << " ms)";
      o << " explains it";
      break;
    }
    case Effect::coil_heating:
      o << "the residual drifts slowly (it follows the integral of the coil drive); a coil "
           "warming with thermal resistance "
        << fmt(value("thermal_resistance")) << " K/W and time constant "
        << fmt(value("thermal_time_constant")) << " s loses current as R(T) rises";
      break;
    case Effect::friction: {
      double opening = 0.0, ratio = 0.0;
      for (const auto& l : st.loops)
        if (l.input == "velocity") opening = l.opening, ratio = l.slow_fast_ratio;
      o << "the residual steps with the sign of the velocity (loop opening " << fmt(opening, 2)
        << " of the residual rms, " << fmt(ratio, 2) << " as wide at slow as at fast rates: "
        << (ratio > 0.5 ? "rate-independent" : "rate-dependent, so friction explains only part")
        << "); a Coulomb force of " << fmt(value("coulomb_force")) << " N explains it";
      break;
    }
    case Effect::pre_yield:
      o << fmt(100 * regime_share(d.mismatch, "flow reversal"), 2)
        << " % of the residual energy sits at flow reversals, where the measured output rolls "
           "over smoothly instead of jumping with the Bingham map: the fluid deforms elastically "
           "before it yields; a linear compliance of "
        << fmt(value("compliance")) << " m^3/Pa per chamber (the same at every amplitude, unlike "
        << "air) explains it";
      break;
    case Effect::magnetic_hysteresis: {
      double memory = 0.0;
      for (const auto& l : st.loops)
        if (l.input == "current" || l.input == "current_cmd") memory = l.memory_opening;
      const double a = value("a"), dd = value("d");
      o << "the output at one current depends on where the current came from: the residual "
           "signed by the direction of the last current change averages "
        << fmt(memory, 2)
        << " of its rms, a loop in (current, residual) that stays open while the current "
           "rests (rate-independent, unlike a lag, which settles); a Duhem field with a = "
        << fmt(a) << " 1/A, d = " << fmt(dd, 2)
        << " (loop half width (1 - d)/a = " << fmt(a > 0 ? (1.0 - dd) / a : 0.0)
        << " A) explains it";
      break;
    }
  }
  if (!st.correlations.empty())
    o << "; strongest residual correlation: " << st.correlations.front().signal << " ("
      << fmt(st.correlations.front().value, 2) << ")";
  return o.str();
}

std::string separating_measurement(Effect a, Effect b) {
  auto pair = [&](Effect x, Effect y) { return (a == x && b == y) || (a == y && b == x); };
  if (pair(Effect::eddy_currents, Effect::mr_response_time))
    return "both are one first-order lag between coil current and yield stress; measure the "
           "flux in the gap (search coil or Hall probe): eddy currents delay the flux behind the "
           "current, a slow MR response does not; or repeat with a laminated core";
  if (pair(Effect::compressibility, Effect::pre_yield))
    return "repeat at two amplitudes: entrained air stiffens as the pressure rises (isothermal "
           "compliance V/p falls with the pressure), the elastic pre-yield branch does not; a "
           "chamber pressure transducer shows air's curved pressure-volume path directly";
  if (pair(Effect::compressibility, Effect::fluid_inertia))
    return "change the frequency: a compliance lag shrinks with stiffer fluid and grows with the "
           "pressure swing, inertia grows with the square of the frequency";
  if (pair(Effect::coil_inductance, Effect::eddy_currents) ||
      pair(Effect::coil_inductance, Effect::mr_response_time))
    return "record the coil current: inductance delays the current itself, field and fluid lags "
           "do not";
  if (a == Effect::magnetic_hysteresis || b == Effect::magnetic_hysteresis)
    return "hold each current level longer and approach it from above and from below: a lag "
           "settles within a few time constants, magnetic hysteresis leaves a lasting offset "
           "that depends on the approach (also at DC); a search coil on the core shows the "
           "flux loop directly";
  return "excite the device at several frequencies and amplitudes: the two effects scale "
         "differently with rate and amplitude";
}

/// A Duhem loop must be wider than this many noise standard deviations of the current.
constexpr double kLoopNoiseRatio = 10.0;

/// Most candidates tried for acceptance at one forward step (each costs a held-out check).
constexpr std::size_t kMaxTries = 3;

double size_relative_se(const DiagnosisModel& model, const ModelFit& fit, int threads,
                        const std::vector<bool>& mask);
double resolved_time_constant(const DiagnosisModel& model, const ModelFit& fit);

/// Effects and parameter values of a model.
struct EffectSet {
  std::vector<Effect> effects;
  std::vector<double> values;
};

/// `fit` with its i-th effect switched off (removed, every other parameter as fitted), and that
/// model's squared error on each sample set of `evidence` (infinite when it cannot be simulated).
std::pair<EffectSet, TwoSse> sse_switched_off(const DiagnosisModel& model, const ModelFit& fit,
                                              std::size_t i, const Evidence& evidence) {
  std::size_t offset = model.static_params().size();
  for (std::size_t j = 0; j < i; ++j) offset += model.effect_params(fit.effects[j]).size();
  const std::size_t k = model.effect_params(fit.effects[i]).size();
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

/// Whether removing `gain` from a residual of `sse` is material: at least `min_share` of the
/// energy above the noise floor `floor_sse` (the share is returned in `share`) and at least
/// `min_noise_multiple` noise deviations in rms (in `rms_in_sigma`).
bool material(double sse, double gain, double floor_sse, const DiagnoseOptions& options,
              double& share, double& rms_in_sigma) {
  const double excess = sse - floor_sse;
  share = excess > 0.0 ? gain / excess : 0.0;
  rms_in_sigma = floor_sse > 0.0 ? std::sqrt(std::max(gain, 0.0) / floor_sse) : 1e300;
  return share >= options.min_share && rms_in_sigma >= options.min_noise_multiple;
}

/// Why a candidate fit that lowered BIC is still not accepted ("" if nothing speaks against it
/// before the held-out check): it removes too small a share of the residual energy above the
/// noise floor (`share` returns the share), its time constant is shorter than a sample, or its
/// size parameter is not identified. Measured on every sample, or (`away`) on the samples away
/// from steps only (Evidence).
std::string rejection(const DiagnosisModel& model, const ModelFit& current, const ModelFit& fit,
                      Effect effect, double delta_bic, const Evidence& evidence, bool away,
                      const DiagnoseOptions& options, double& share) {
  const std::string head = effect_name(effect) + " lowered BIC by " + fmt(delta_bic) +
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
  // A time constant shorter than one sample interval cannot be told from the recording's own
  // timing (channel skew, held drives), which the delay nuisance already absorbs; except a coil
  // inductance fitted to the coil current itself (the output of a coil bench): there the L/R
  // lag is the only dynamics between the recorded voltage and the recorded output, and its
  // exponential approach after each step is not a shift (a delay moves the whole step; the
  // lag's remainder decays over the following samples at a rate the step heights fix).
  const bool lag_on_output =
      effect == Effect::coil_inductance && model.output_column() == "current";
  if (const double tau = resolved_time_constant(model, fit);
      tau > 0.0 && tau < model.sample_interval() && !lag_on_output)
    return head + " with a time constant of " + fmt(1e3 * tau) +
           " ms, shorter than one sample interval (" + fmt(1e3 * model.sample_interval()) +
           " ms): not told apart from the recording's timing; not accepted";
  // A hysteresis loop narrower than ten noise standard deviations of the current is what a
  // Duhem block does to a noisy current (it follows the noise and low-passes it), not a loop.
  if (effect == Effect::magnetic_hysteresis && model.drive_noise().count("current")) {
    const std::size_t j = fit.layout.size() - 2;
    const double half_width = (1.0 - fit.values[j + 1]) / fit.values[j];
    const double noise = model.drive_noise().at("current");
    if (half_width < kLoopNoiseRatio * noise)
      return head + " with a loop half width (1 - d)/a of " + fmt(half_width) + " A, less than " +
             fmt(kLoopNoiseRatio, 2) + " times the current's noise (" + fmt(noise) +
             " A): not told apart from the noise; not accepted";
  }
  // Identifiability: the effect's size parameter known to a relative standard error below
  // max_relative_se.
  const double rse =
      size_relative_se(model, fit, options.threads, away ? evidence.away : std::vector<bool>{});
  if (!(rse < options.max_relative_se))
    return head + " but its " + model.effect_params(effect).front().name +
           " is not identified (relative standard error " +
           (std::isfinite(rse) ? fmt(100 * rse, 2) + " %" : std::string("unbounded")) +
           "): not accepted";
  return "";
}

/// Drops from `d` (and from `fit`, the final joint re-fit) each finding that no longer passes the
/// practical-significance and noise bars inside the joint model: switched off there with every
/// other parameter as fitted, the error rises by less than `min_share` of the residual above the
/// noise floor or less than `min_noise_multiple` noise deviations in rms. A finding accepted
/// beside another can fade in the joint re-fit (a Coulomb force that ends at a few newtons
/// once a compliance and the static map are re-fitted with it); it is then not reported.
void drop_faded_findings(const DiagnosisModel& model, ModelFit& fit, const Evidence& evidence,
                         const DiagnoseOptions& options, Diagnosis& d) {
  bool dropped = true;
  while (dropped && fit.effects.size() > 1) {
    dropped = false;
    for (std::size_t i = 0; i < fit.effects.size(); ++i) {
      const auto [without, sse_off] = sse_switched_off(model, fit, i, evidence);
      if (!std::isfinite(sse_off.all)) continue;
      const TwoSse with{fit.sse, two_sse(model.measured(), fit.prediction, evidence).away};
      double share = 0.0, share_away = 0.0, rms = 0.0;
      if (material(sse_off.all, sse_off.all - with.all, evidence.floor_all, options, share, rms) ||
          (!evidence.away.empty() && material(sse_off.away, sse_off.away - with.away,
                                              evidence.floor_away, options, share_away, rms)))
        continue;
      const Effect e = fit.effects[i];
      d.notes.push_back(effect_name(e) +
                        " was accepted in forward selection but in the joint "
                        "re-fit it explains only " +
                        fmt(100 * std::max(share, share_away), 2) +
                        " % of the residual energy above the noise floor: not reported");
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

/// Static start values; the pre-yield smoothness (when calibrated) from a decade grid, since a
/// plug switch much narrower than a sample's flow step leaves the error flat in it.
std::vector<double> nuisance_start(const DiagnosisModel& model, int threads) {
  const auto layout = model.static_params();
  std::vector<double> start;
  for (const auto& p : layout) start.push_back(p.nominal);
  const std::size_t j = layout.size() - 1;
  if (layout[j].name != "preyield_flow") return start;
  std::vector<double> grid;
  for (double v = layout[j].lower; v <= layout[j].upper * 1.0001; v *= std::sqrt(10.0))
    grid.push_back(v);
  return grid_search(model, {}, std::move(start), j, grid, nullptr, threads);
}

/// The nuisances of a fitted model.
Nuisance nuisance_of(const DiagnosisModel& model, const ModelFit& fit) {
  Nuisance u;
  u.drive_noise = model.drive_noise();
  u.velocity_filter_bandwidth = model.velocity_filter_bandwidth();
  for (std::size_t j = 0; j < model.static_params().size(); ++j) {
    if (fit.layout[j].name == "delay") u.delay = fit.values[j];
    if (fit.layout[j].name == "preyield_flow") u.preyield_flow = fit.values[j];
  }
  u.delay_samples = u.delay / model.sample_interval();
  if (model.peak_flow() > 0.0) u.preyield_fraction = u.preyield_flow / model.peak_flow();
  u.drive_sampling = model.sampling();
  const double frac = std::abs(u.delay_samples);
  u.sampling =
      std::string(u.drive_sampling == DriveSampling::held
                      ? "drives held between samples (the coil drive a zero-order hold, each "
                        "sample standing for the interval it begins; the motion read at the "
                        "interval's middle)"
                      : "drives linear between samples") +
      "; " +
      (frac < 0.25 ? std::string("output and drives aligned")
                   : std::string(u.delay_samples > 0 ? "output behind" : "output ahead of") +
                         " the drives by " + fmt(frac, 2) + " samples (channel skew" +
                         (u.drive_sampling == DriveSampling::linear
                              ? ", or drives recorded as held samples, which a linear reading "
                                "sees half a sample late)"
                              : ")")) +
      "; calibrated, not physics";
  return u;
}

/// The time constant [s] the last effect of `fit` adds (field lags; L/R of a coil inductance),
/// 0 for effects that are not a time constant.
double resolved_time_constant(const DiagnosisModel& model, const ModelFit& fit) {
  const Effect e = fit.effects.back();
  const double size = fit.values[fit.layout.size() - model.effect_params(e).size()];
  if (e == Effect::eddy_currents || e == Effect::mr_response_time) return size;
  if (e == Effect::coil_inductance)
    return size / model.spec(fit.effects, fit.values).coil.resistance_20c;
  return 0.0;
}

/// Relative standard error of the size parameter (the first) of the last effect of `fit`, on the
/// samples of `mask` (all when empty).
double size_relative_se(const DiagnosisModel& model, const ModelFit& fit, int threads,
                        const std::vector<bool>& mask) {
  FitSettings s;
  s.mask = mask;
  s.max_iterations = 0;
  s.threads = threads;
  s.fixed = held_in_candidates(model, fit.effects, fit.values);
  const auto f = fit_model(model, fit.effects, fit.values, s);
  const std::size_t j = f.layout.size() - model.effect_params(f.effects.back()).size();
  const double v = std::abs(f.values[j]);
  return v > 0.0 ? f.standard_errors[j] / v : std::numeric_limits<double>::infinity();
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

/// Progress of one diagnosis: each finished stage with its own time, each candidate's result,
/// timed from the start of the run.
class Clock {
 public:
  using time_point = std::chrono::steady_clock::time_point;
  explicit Clock(const ProgressCallback& progress) : progress_(progress) {}
  /// [s] since `t`.
  static double since(time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }
  /// [s] since the run started.
  double elapsed() const { return since(start_); }
  /// Reports `event` to the listener, if any (its elapsed time set here).
  void report(ProgressEvent event) const {
    if (!progress_) return;
    event.elapsed = elapsed();
    progress_(event);
  }
  /// A finished stage: its name and its own time in the detail.
  void stage(const std::string& what) {
    const auto now = std::chrono::steady_clock::now();
    report({what, 0.0, 0.0, 0.0,
            "in " + num(std::chrono::duration<double>(now - stage_).count()) + " s"});
    stage_ = now;
  }

 private:
  const ProgressCallback& progress_;
  time_point start_ = std::chrono::steady_clock::now();
  time_point stage_ = start_;
};

/// Forward selection on `model` from its calibrated baseline `current`: candidates are fitted,
/// tested and accepted one at a time (scores, findings and notes appended to `d`); returns the
/// fit of the last accepted model (`current` itself when nothing is accepted). `evidence` holds
/// the noise floor n sigma^2 of this model's baseline residual and the samples away from its
/// steps; ΔBIC, practical significance and the held-out gain are each met on every sample or
/// on the samples away from steps.
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
  const auto candidates = model.applicable_effects();
  for (int step = 0; step < options.max_effects; ++step) {
    struct Tried {
      Effect effect;
      ModelFit fit;
      double delta_bic;
    };
    std::vector<Tried> tried;
    // The current model with its best output delay (one simulation): each candidate is fitted
    // with the delay free, so the gain it is credited with must not be the delay's.
    if (!held_in_candidates(model, current.effects, current.values)[model.delay_index()])
      polish_delay(model, current);
    if (step > 0) recalibrate_nuisances(model, current, settings);
    const double bic_now = bic(current.sse, n, current.values.size());
    const bool first_step = step == 0;
    for (Effect c : candidates) {
      if (std::find(current.effects.begin(), current.effects.end(), c) != current.effects.end())
        continue;
      // After the first step, candidates that made the fit clearly worse are not retried.
      if (!first_step && !worth_retrying(d.candidates, c, step, options.bic_margin)) continue;
      // Eddy currents and MR response time are the same first-order lag block in the rig model:
      // when neither is in yet, the second is the first's fit under another name.
      if (c == Effect::eddy_currents && !has_effect(current, Effect::mr_response_time)) {
        auto twin = std::find_if(tried.begin(), tried.end(), [](const auto& t) {
          return t.effect == Effect::mr_response_time;
        });
        if (twin != tried.end()) {
          d.candidates.push_back(
              {c, step, fit_percent_of(y, twin->fit.prediction), twin->delta_bic});
          tried.push_back({c, twin->fit, twin->delta_bic});
          tried.back().fit.effects.back() = c;
          continue;
        }
      }
      auto effects = current.effects;
      effects.push_back(c);
      auto s = current.values;
      for (const auto& p : model.effect_params(c)) s.push_back(p.nominal);
      try {
        const auto started = std::chrono::steady_clock::now();
        double grid_sse = 0.0;
        const bool scan_delay = !held_in_candidates(model, effects, s)[model.delay_index()];
        // The inertance is also started at the ringing the residual shows (omega^2 = 1 / (I C)
        // with the compliance already in the model): the error is multimodal in it.
        const auto starts = c == Effect::fluid_inertia && options.ringing_start
                                ? ringing_inertances(model, current)
                                : std::vector<double>{};
        s = grid_start(model, effects, s, &grid_sse, options.threads, scan_delay, starts);
        // Screening: a candidate that lowers the error at no decade of its parameter (the
        // others held at the current fit) is scored there and not fitted.
        if (!(grid_sse < current.sse)) {
          const double db = bic_now - bic(grid_sse, n, s.size());
          d.candidates.push_back({c, step, 0.0, db, true});
          clock.report({"step " + std::to_string(step + 1) + " " + effect_name(c), 0.0, 0.0, 0.0,
                        "screened out (no decade of its parameter helps)"});
          continue;
        }
        auto candidate_settings = settings;
        candidate_settings.fixed = held_in_candidates(model, effects, current.values);
        auto f = fit_model(model, effects, s, candidate_settings);
        const double db = bic_now - bic(f.sse, n, f.values.size());
        clock.report({"step " + std::to_string(step + 1) + " " + effect_name(c), 0.0, 0.0, 0.0,
                      "dBIC " + num(db) + " in " + num(Clock::since(started)) + " s"});
        d.candidates.push_back({c, step, fit_percent_of(y, f.prediction), db});
        tried.push_back({c, std::move(f), db});
      } catch (const ConvergenceError&) {
        d.notes.push_back("candidate " + effect_name(c) + " could not be simulated at step " +
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
    std::vector<Effect> rejected;
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
      clock.stage("held-out check of " + effect_name(c.effect));
      if (gain < options.heldout_margin) {
        d.notes.push_back(effect_name(c.effect) + " lowered BIC by " + fmt(c.delta_bic) +
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
    f.fit_percent = fit_percent_of(y, best.fit.prediction);
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
        const auto how = separating_measurement(best.effect, tried[i].effect);
        if (f.separating_measurement.find(how) == std::string::npos)
          f.separating_measurement += (f.separating_measurement.empty() ? "" : "; ") + how;
      }
    d.findings.push_back(std::move(f));
    current = best.fit;
    held_current = held_new;
  }

  return current;
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
                            model.sampling());
  const auto stiff = fit_model(part, {}, baseline.values, calib);
  const auto compliant = fit_model(part.with_oil_compliance(0.0), {}, baseline.values, calib);
  return compliant.sse < stiff.sse;
}

}  // namespace

Diagnosis diagnose(const lumped::Recording& rec, const DiagnoseOptions& options) {
  Clock clock(options.progress);
  const ModelBaseline* fitted = options.baseline_model ? &*options.baseline_model : nullptr;
  auto chosen = std::make_unique<DiagnosisModel>(rec, fitted);
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
      const double gain = fit_percent_of(chosen->measured(), compliant_fit.prediction) -
                          fit_percent_of(chosen->measured(), d.baseline.prediction);
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
    other_fit_percent = fit_percent_of(chosen->measured(), held_fit.prediction);
  }
  const DiagnosisModel& model = *chosen;
  d.output_column = model.output_column();
  d.t = rec.t;
  d.measured = model.measured();
  const auto& y = model.measured();
  const std::size_t n = y.size();
  d.baseline_fit_percent = fit_percent_of(y, d.baseline.prediction);
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
    DiagnosisModel part(lumped::excerpt(rec, d.selection), fitted, model.sampling());
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
  // (with its standard errors).
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
    drop_faded_findings(model, current, evidence, options, d);
  }
  clock.stage("joint re-fit");
  d.final_fit = current;
  d.final_fit_percent = fit_percent_of(y, current.prediction);
  d.final_stats = residual_statistics(model.recording(), rec.meta.drive, y, current.prediction);
  for (std::size_t k = 0; k < n; ++k) residual[k] = y[k] - current.prediction[k];
  d.final_mismatch = locate_mismatch(model.recording(), residual);
  d.unexplained = unexplained_of(residual, d.baseline.sse, sigma);
  d.final_nuisance = nuisance_of(model, current);
  d.final_nuisance.sampling_fit_gain = d.nuisance.sampling_fit_gain;
  std::size_t offset = model.static_params().size();
  for (auto& f : d.findings) {
    for (const auto& p : model.effect_params(f.effect)) {
      f.param_names.push_back(p.name);
      f.params.push_back(current.values[offset]);
      f.standard_errors.push_back(current.standard_errors[offset]);
      ++offset;
    }
    f.evidence = evidence_for(f.effect, d, current);
    if (!f.ruled_out_by_current.empty()) {
      f.evidence += "; the output alone fits as well with";
      for (Effect e : f.ruled_out_by_current) f.evidence += " " + effect_name(e);
      f.evidence += ", but the measured coil current rules that out";
    }
  }
  const bool chamber_finding = std::any_of(d.findings.begin(), d.findings.end(), [](const auto& f) {
    return f.effect == Effect::compressibility || f.effect == Effect::pre_yield;
  });
  if (!model.chamber_volume_given() && chamber_finding)
    d.notes.push_back(
        "[rig] chamber_volume not given: compressibility assumed 2e-5 m^3 of oil "
        "per chamber");
  if (model.fitted_baseline())
    d.notes.push_back(
        "the baseline is a fitted model: compressibility, pre_yield and coil_heating sit inside "
        "the rig's hydraulic or electric loop and are not candidates on it");
  if (model.constant_field())
    d.notes.push_back("the recording has no coil input: the field is taken as constant");
  if (d.findings.empty() && !d.baseline_stats.white)
    d.notes.push_back("the residual is not white but no candidate explains it significantly");
  return d;
}

namespace {

nlohmann::json nuisance_json(const Nuisance& u) {
  nlohmann::json j = {
      {"delay", u.delay},
      {"delay_samples", u.delay_samples},
      {"sampling", u.sampling},
      {"drive_sampling", kDriveSamplingNames.name(u.drive_sampling)},
      {"sampling_fit_gain",
       std::isfinite(u.sampling_fit_gain) ? nlohmann::json(u.sampling_fit_gain) : nlohmann::json()},
      {"drive_noise", u.drive_noise},
      {"velocity_filter_bandwidth", u.velocity_filter_bandwidth}};
  if (u.preyield_flow > 0.0) {
    j["preyield_flow"] = u.preyield_flow;
    j["preyield_fraction_of_peak_flow"] = u.preyield_fraction;
  }
  return j;
}

}  // namespace

nlohmann::json diagnosis_json(const Diagnosis& d) {
  using nlohmann::json;
  auto params_of = [](const ModelFit& f, std::size_t from, std::size_t to) {
    json p = json::object();
    for (std::size_t j = from; j < to; ++j) p[f.layout[j].name] = f.values[j];
    return p;
  };
  const std::size_t n_static = d.baseline.values.size();
  json out;
  out["recording"] = d.recording;
  out["baseline"] = {{"fit_percent", d.baseline_fit_percent},
                     {"params", params_of(d.baseline, 0, n_static)},
                     {"includes", json::array()},
                     {"nuisance", nuisance_json(d.nuisance)}};
  for (const auto& item : d.includes)
    out["baseline"]["includes"].push_back(
        {{"name", item.name},
         {"value", item.unit.empty() && item.value == 0.0 ? json() : json(item.value)},
         {"unit", item.unit},
         {"source", item.source}});
  out["mismatch"] = json::array();
  for (const auto& w : d.mismatch)
    out["mismatch"].push_back({{"t_start", w.t_start},
                               {"t_end", w.t_end},
                               {"share_of_residual", w.share},
                               {"regime", w.regime}});
  out["missing_physics"] = json::array();
  for (const auto& f : d.findings) {
    json p = json::object(), u = json::object();
    for (std::size_t j = 0; j < f.params.size(); ++j) {
      p[f.param_names[j]] = f.params[j];
      u[f.param_names[j]] =
          std::isfinite(f.standard_errors[j]) ? json(f.standard_errors[j]) : json();
    }
    if (f.effect == Effect::compressibility && !f.params.empty())
      p["hydraulic_capacitance"] = f.params[0] / 1e5;  // isothermal air at the 1e5 Pa precharge
    json e = {{"name", effect_name(f.effect)},
              {"params", p},
              {"standard_errors", u},
              {"fit_percent", f.fit_percent},
              {"delta_bic", f.delta_bic},
              {"heldout_gain", f.heldout_gain},
              {"share_of_residual_above_noise", f.share},
              {"evidence", f.evidence}};
    if (!f.ruled_out_by_current.empty()) {
      e["ruled_out_by_measured_current"] = json::array();
      for (Effect a : f.ruled_out_by_current)
        e["ruled_out_by_measured_current"].push_back(effect_name(a));
    }
    if (!f.ambiguous_with.empty()) {
      e["ambiguous_with"] = json::array();
      for (Effect a : f.ambiguous_with) e["ambiguous_with"].push_back(effect_name(a));
      e["separating_measurement"] = f.separating_measurement;
    }
    out["missing_physics"].push_back(e);
  }
  out["final"] = {{"fit_percent", d.final_fit_percent},
                  {"params", params_of(d.final_fit, 0, d.final_fit.values.size())},
                  {"nuisance", nuisance_json(d.final_nuisance)}};
  out["unexplained"] = {{"share_of_residual", d.unexplained.share},
                        {"share_of_baseline_residual", d.unexplained.baseline_share},
                        {"noise_floor_rms", d.unexplained.noise_sigma},
                        {"residual_rms", d.unexplained.residual_rms}};
  json stats;
  stats["whiteness"] = {{"lag1_autocorrelation", d.baseline_stats.lag1_autocorrelation},
                        {"ljung_box_q", d.baseline_stats.ljung_box_q},
                        {"white", d.baseline_stats.white}};
  stats["correlations"] = json::array();
  for (const auto& c : d.baseline_stats.correlations)
    stats["correlations"].push_back({{"signal", c.signal}, {"value", c.value}, {"lag", c.lag}});
  stats["loops"] = json::array();
  for (const auto& l : d.baseline_stats.loops)
    stats["loops"].push_back({{"input", l.input},
                              {"opening", l.opening},
                              {"slow_fast_ratio", l.slow_fast_ratio},
                              {"rate_independent", l.rate_independent}});
  stats["output_lag"] = d.baseline_stats.output_lag;
  stats["final_white"] = d.final_stats.white;
  out["residual_statistics"] = stats;
  out["candidates"] = json::array();
  for (const auto& c : d.candidates)
    out["candidates"].push_back(
        {{"name", effect_name(c.effect)},
         {"step", c.step + 1},
         {"fit_percent", c.screened ? nlohmann::json() : nlohmann::json(c.fit_percent)},
         {"screened", c.screened},
         {"delta_bic", c.delta_bic}});
  if (d.selection.size() > 0)
    out["selection_samples"] = {{"begin", d.selection.begin}, {"end", d.selection.end}};
  out["notes"] = d.notes;
  return out;
}

}  // namespace rheomag::diagnose
