// What one recording cannot tell a named effect's size from: the output delay's trade and the
// effects of the same shape.

#include "diagnose/size_sensitivity.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace rheomag::diagnose {

namespace {

/// Index in `effects`' layout of the first parameter of `c` (the layout's size when absent).
std::size_t first_param_of(const DiagnosisModel& model,
                           const std::vector<const Candidate*>& effects, const Candidate* c) {
  std::size_t at = model.static_params().size();
  for (const Candidate* e : effects) {
    if (e == c) return at;
    at += e->params(model).size();
  }
  return at;
}

/// `fit`'s effect `c`'s parameters, the size replaced by `size`, as derived quantities.
std::vector<DerivedParam> derived_at(const DiagnosisModel& model, const ModelFit& fit,
                                     const Candidate* c, double size) {
  const std::size_t at = first_param_of(model, fit.effects, c);
  std::vector<double> params(
      fit.values.begin() + static_cast<std::ptrdiff_t>(at),
      fit.values.begin() + static_cast<std::ptrdiff_t>(at + c->params(model).size()));
  params.front() = size;
  return c->derived_params(model, params);
}

/// `fit` refitted with its output delay held at `delay`; throws ConvergenceError when it cannot
/// be simulated.
ModelFit refit_at_delay(const DiagnosisModel& model, const ModelFit& fit, double delay,
                        int max_iterations, int threads) {
  FitSettings settings;
  settings.max_iterations = max_iterations;
  settings.threads = threads;
  settings.standard_errors = false;
  settings.signed_linear_sizes = true;
  settings.fixed.assign(fit.values.size(), false);
  settings.fixed[model.delay_index()] = true;
  auto start = fit.values;
  start[model.delay_index()] = delay;
  return fit_model(model, fit.effects, start, settings);
}

}  // namespace

double shape_dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) s += a[k] * b[k];
  return s;
}

std::vector<double> unit_output_shape(const DiagnosisModel& model, const ModelFit& fit,
                                      const Candidate* c) {
  auto effects = fit.effects;
  auto values = fit.values;
  if (std::find(effects.begin(), effects.end(), c) == effects.end()) {
    effects.push_back(c);
    for (const ParamDef& p : c->params(model)) values.push_back(p.nominal);
    values[first_param_of(model, effects, c)] = 0.0;
  }
  const std::size_t at = first_param_of(model, effects, c);
  const double step = 0.1 * c->params(model).front().upper;
  const auto base = model.predict(effects, values);
  values[at] += step;
  const auto moved = model.predict(effects, values);
  std::vector<double> shape(base.size());
  double mean = 0.0;
  for (std::size_t k = 0; k < shape.size(); ++k) {
    shape[k] = (moved[k] - base[k]) / step;
    mean += shape[k] / static_cast<double>(shape.size());
  }
  for (double& v : shape) v -= mean;
  return shape;
}

std::vector<SizeSensitivity> size_sensitivities(
    const DiagnosisModel& model, const ModelFit& fit,
    const std::vector<const Candidate*>& linear_candidates, int max_iterations, int threads) {
  std::vector<SizeSensitivity> out(fit.effects.size());
  std::vector<std::size_t> linear;  // indices in fit.effects
  for (std::size_t i = 0; i < fit.effects.size(); ++i)
    if (fit.effects[i]->linear_in_size(model)) linear.push_back(i);
  if (linear.empty()) return out;

  // The delay's trade: one sample either side, inside the bounds.
  const std::size_t j = model.delay_index();
  const double delay = fit.values[j];
  const double h = model.sample_interval();
  const double lo = std::max(delay - h, fit.layout[j].lower);
  const double hi = std::min(delay + h, fit.layout[j].upper);
  if (hi - lo >= 0.5 * h) {
    try {
      const ModelFit early = refit_at_delay(model, fit, lo, max_iterations, threads);
      const ModelFit late = refit_at_delay(model, fit, hi, max_iterations, threads);
      for (const std::size_t i : linear) {
        const Candidate* c = fit.effects[i];
        const std::size_t at = first_param_of(model, fit.effects, c);
        out[i].per_delay = (late.values[at] - early.values[at]) / (hi - lo);
        out[i].derived_per_delay = derived_at(model, fit, c, out[i].per_delay);
      }
    } catch (const ConvergenceError&) {
      // a model that cannot be simulated a sample later or earlier: no delay trade reported
    }
  }

  // The twins: other linear effects with this one's output shape on this drive.
  std::vector<std::vector<double>> shapes;
  for (const Candidate* c : linear_candidates) shapes.push_back(unit_output_shape(model, fit, c));
  for (const std::size_t i : linear) {
    const Candidate* c = fit.effects[i];
    const auto own = std::find(linear_candidates.begin(), linear_candidates.end(), c) -
                     linear_candidates.begin();
    if (static_cast<std::size_t>(own) == linear_candidates.size()) continue;
    const auto& a = shapes[static_cast<std::size_t>(own)];
    const double aa = shape_dot(a, a);
    for (std::size_t k = 0; k < linear_candidates.size(); ++k) {
      const double bb = shape_dot(shapes[k], shapes[k]);
      if (linear_candidates[k] == c || !(aa > 0.0) || !(bb > 0.0)) continue;
      const double ab = shape_dot(a, shapes[k]);
      const double correlation = ab / std::sqrt(aa * bb);
      if (std::abs(correlation) < kOneForce) continue;
      ShapeTwin twin;
      twin.effect = linear_candidates[k];
      twin.param = twin.effect->params(model).front().name;
      twin.unit = twin.effect->params(model).front().unit;
      twin.correlation = correlation;
      twin.size_per_unit = ab / aa;
      twin.derived_per_unit = derived_at(model, fit, c, twin.size_per_unit);
      if (twin.size_per_unit != 0.0) {
        twin.same_force_at = fit.values[first_param_of(model, fit.effects, c)] / twin.size_per_unit;
        twin.same_force_derived = twin.effect->derived_params(model, {twin.same_force_at});
      }
      out[i].twins.push_back(std::move(twin));
    }
  }
  return out;
}

}  // namespace rheomag::diagnose
