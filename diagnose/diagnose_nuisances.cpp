// The baseline's nuisances during selection.

#include "diagnose/diagnose_nuisances.hpp"

#include <cmath>

#include "core/error.hpp"
#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_text.hpp"

namespace rheomag::diagnose {

std::vector<bool> nuisances_held(const DiagnosisModel& model,
                                 const std::vector<const Candidate*>& effects) {
  std::vector<bool> held(model.layout(effects).size(), false);
  const std::size_t n_static = model.static_params().size();
  for (std::size_t j = n_static - model.nuisance_count(); j < n_static; ++j) held[j] = true;
  return held;
}

std::vector<bool> held_in_candidates(const DiagnosisModel& model,
                                     const std::vector<const Candidate*>& effects,
                                     const std::vector<double>& values) {
  auto held = nuisances_held(model, effects);
  const auto layout = model.static_params();
  for (std::size_t j = model.delay_index(); j < layout.size(); ++j) {
    const auto& p = layout[j];
    const double v = values[j];
    const bool at_bound = p.log_scale ? v <= p.lower * 1.001 || v >= p.upper / 1.001
                                      : std::abs(v - p.lower) < 5e-4 * (p.upper - p.lower) ||
                                            std::abs(v - p.upper) < 5e-4 * (p.upper - p.lower);
    // The map's knee is a shape the baseline calibrates once: free beside a candidate it would
    // trade its curvature for the candidate's (an air pocket's or a mass's rounding of a
    // reversal), so it stays held until the final joint re-fit.
    if (!at_bound && p.name != "slit_fraction") held[j] = false;
  }
  return held;
}

bool keep_better_with_free_delay(const DiagnosisModel& model,
                                 const std::vector<const Candidate*>& effects,
                                 const std::vector<double>& nominal, const FitSettings& held,
                                 const std::vector<double>& starts, int threads, ModelFit& fit) {
  auto settings = held;
  settings.fixed[model.delay_index()] = false;
  try {
    const auto start = grid_start(model, effects, nominal, nullptr, threads, true, starts);
    auto free = fit_model(model, effects, start, settings);
    if (!(free.sse < fit.sse)) return false;
    fit = std::move(free);
    return true;
  } catch (const ConvergenceError&) {
    return false;  // the held fit stands
  }
}

DelayAlignment align_unrequired_delay(const DiagnosisModel& model, ModelFit& fit,
                                      const FitSettings& settings, double margin) {
  DelayAlignment a;
  const std::size_t j = model.delay_index();
  const double n = static_cast<double>(fit.samples);
  if (fit.values[j] == 0.0 || !(n > 1.0) || !(fit.sse > 0.0) || !std::isfinite(fit.sse)) return a;
  auto s = settings;
  s.fixed.assign(fit.values.size(), false);
  s.fixed[j] = true;
  auto start = fit.values;
  start[j] = 0.0;
  try {
    auto aligned = fit_model(model, fit.effects, start, s);
    if (aligned.sse < fit.sse) {
      // The delayed fit stopped short of its optimum: free the delay again from the aligned fit.
      auto refit = fit_model(model, fit.effects, aligned.values, settings);
      if (refit.sse < fit.sse) fit = std::move(refit);
    }
    a.tried = true;
    a.delay = fit.values[j];
    a.delta_bic = n * std::log(aligned.sse / fit.sse) - std::log(n);
    a.aligned = a.delta_bic <= margin;
    if (a.aligned) fit = std::move(aligned);
  } catch (const ConvergenceError&) {
    // the delayed fit stands
  }
  return a;
}

void recalibrate_nuisances(const DiagnosisModel& model, ModelFit& fit, const FitSettings& base) {
  auto free = held_in_candidates(model, fit.effects, fit.values);
  bool any = false;
  std::vector<bool> fixed(fit.values.size(), true);
  const auto layout = model.static_params();
  for (std::size_t j = model.delay_index(); j < layout.size(); ++j)
    if (!free[j] || layout[j].name == "slit_fraction") fixed[j] = false, any = true;
  if (!any) return;
  auto s = base;
  s.fixed = fixed;
  auto f = fit_model(model, fit.effects, fit.values, s);
  if (f.sse < fit.sse) fit = std::move(f);
}

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

std::vector<double> nuisance_start(const DiagnosisModel& model, int threads) {
  const auto layout = model.static_params();
  std::vector<double> start;
  for (const auto& p : layout) start.push_back(p.nominal);
  // A grid over each shape nuisance in turn (the fit from a grid point finds the rest): the
  // pre-yield smoothness in half decades, then the knee between the line and the slit law.
  for (std::size_t j = model.delay_index(); j < layout.size(); ++j) {
    std::vector<double> grid;
    if (layout[j].name == "preyield_flow")
      for (double v = layout[j].lower; v <= layout[j].upper * 1.0001; v *= std::sqrt(10.0))
        grid.push_back(v);
    else if (layout[j].name == "slit_fraction")
      grid = {0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0};
    if (!grid.empty()) start = grid_search(model, {}, std::move(start), j, grid, nullptr, threads);
  }
  return start;
}

Nuisance nuisance_of(const DiagnosisModel& model, const ModelFit& fit) {
  Nuisance u;
  u.drive_noise = model.drive_noise();
  u.velocity_filter_bandwidth = model.velocity_filter_bandwidth();
  u.current_reversal_band = model.current_reversal_band();
  for (const auto& [column, glitches] : model.motion_glitches())
    u.motion_glitches[column] = glitches.samples.size();
  for (std::size_t j = 0; j < model.static_params().size(); ++j) {
    if (fit.layout[j].name == "delay") u.delay = fit.values[j];
    if (fit.layout[j].name == "preyield_flow") u.preyield_flow = fit.values[j];
    if (fit.layout[j].name == "slit_fraction") u.slit_fraction = fit.values[j];
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

}  // namespace rheomag::diagnose
