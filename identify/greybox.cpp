// Grey-box fits: Ceres Levenberg-Marquardt with bounds on normalised parameters, residuals from a
// fixed-step RK4 free-run simulation differentiated by Jets; reported output from rosenbrock4.
// The Ceres fit itself is compiled once per parameter count (greybox_fit_*.cpp).

#include "identify/greybox.hpp"

#include <glog/logging.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <stdexcept>

#include "core/error.hpp"
#include "core/format_text.hpp"
#include "identify/greybox_fit_data.hpp"
#include "identify/multistart_fit.hpp"
#include "identify/standard_errors.hpp"
#include "lumped/ode.hpp"
#include "lumped/output_smoothing.hpp"

namespace rheomag::identify {

namespace greybox_detail {

std::string unit_string(const std::string& pattern, const lumped::GreyboxSetup& s) {
  const bool pressure = s.output_column == "pressure";
  const bool flow = s.motion_column == "flow";
  const std::string Y = pressure ? "Pa" : "N", M = flow ? "m^3/s" : "m/s", X = flow ? "m^3" : "m",
                    U = s.field_column == "command" ? "V" : "A";
  std::string out;
  for (char c : pattern) {
    if (c == 'Y')
      out += Y;
    else if (c == 'M')
      out += M;
    else if (c == 'X')
      out += X;
    else if (c == 'U')
      out += U;
    else
      out += c;
  }
  return out;
}

double fit_step(lumped::PhenoKind kind, const GreyboxOptions& options) {
  if (kind == lumped::PhenoKind::bouc_wen) return options.bouc_wen_step;
  return kind == lumped::PhenoKind::damper ? options.exponential_step : options.max_substep;
}

}  // namespace greybox_detail

namespace {

using greybox_detail::FitData;
using greybox_detail::ParamGuess;
using greybox_detail::run_fit;

/// Number of distinct values the field input takes in `d` on `r`, counted up to `cap`.
std::size_t field_levels(const lumped::DriveSeries& d, lumped::SampleRange r, std::size_t cap) {
  std::vector<double> levels;
  for (std::size_t i = r.begin; i < r.end && levels.size() < cap; ++i)
    if (std::find(levels.begin(), levels.end(), d.field[i]) == levels.end())
      levels.push_back(d.field[i]);
  return levels.size();
}

ParamGuess initial_guess(lumped::PhenoKind kind, const lumped::DriveSeries& d,
                         lumped::SampleRange r, double orientation, bool has_field, bool periodic) {
  double ymin = 1e300, ymax = -1e300, ymean = 0.0, mmax = 0.0, umax = 0.0;
  for (std::size_t i = r.begin; i < r.end; ++i) {
    double y = orientation * d.y[i];
    ymin = std::min(ymin, y);
    ymax = std::max(ymax, y);
    ymean += y;
    mmax = std::max(mmax, std::abs(d.motion[i]));
    umax = std::max(umax, std::abs(d.field[i]));
  }
  ymean /= static_cast<double>(r.size());
  const double F = std::max(0.5 * (ymax - ymin), 1e-300);
  const double M = std::max(lumped::rms_on(d.motion, r), 1e-300);
  const double X = std::max(lumped::rms_on(d.position, r), 1e-300);
  const double U = umax > 0.0 ? umax : 1.0;
  const double Acc = std::max(lumped::rms_on(d.acceleration, r), 1e-300);
  ParamGuess g;
  // add(nominal, scale, lower, upper, field_term)
  auto add = [&](double nominal, double scale, double lower, double upper, bool field_term) {
    g.nominal.push_back(field_term && !has_field ? 0.0 : nominal);
    g.scale.push_back(scale);
    g.lower.push_back(lower);
    g.upper.push_back(upper);
    g.fixed.push_back(field_term && !has_field);
  };
  switch (kind) {
    case lumped::PhenoKind::bingham:
      add(0.5 * F, F, 0.0, 10 * F, false);
      add(0.0, F / U, -10 * F / U, 10 * F / U, true);
      add(0.5 * F / M, F / M, 0.0, 100 * F / M, false);
      add(0.0, F / (M * U), -100 * F / (M * U), 100 * F / (M * U), true);
      add(0.1 * M, M, 1e-4 * M, 10 * M, false);
      add(ymean, F, ymean - 10 * F, ymean + 10 * F, false);
      break;
    case lumped::PhenoKind::lugre: {
      const double rate = 10.0 / X;
      add(0.5 * F, F, 0.0, 10 * F, false);
      add(0.0, F / U, -10 * F / U, 10 * F / U, true);
      add(0.0, F / (rate * M), -10 * F / (rate * M), 10 * F / (rate * M), false);
      add(rate, rate, 0.01 * rate, 1000 * rate, false);
      add(0.3 * F, F, 0.0, 10 * F, false);
      add(0.0, F / U, -10 * F / U, 10 * F / U, true);
      add(1.0, 1.0, 0.2, 2.0, false);
      add(ymean, F, ymean - 10 * F, ymean + 10 * F, false);
      break;
    }
    case lumped::PhenoKind::bouc_wen: {
      // Shapes of Spencer et al. 1997 scaled to this recording: z saturates near X/2.
      const double A = 301.0, gamma = 2.0 * A / (X * X);
      const double c0 = 0.3 * F / M;
      add(F / X, F / X, 0.0, 100 * F / X, false);                          // alpha_a
      add(0.0, F / (X * U), -100 * F / (X * U), 100 * F / (X * U), true);  // alpha_b
      add(c0, c0, 0.0, 100 * c0, false);                                   // c0_a
      add(0.0, c0 / U, -100 * c0 / U, 100 * c0 / U, true);                 // c0_b
      add(10 * c0, 10 * c0, 0.0, 1e5 * c0, false);                         // c1_a
      add(0.0, 10 * c0 / U, -1000 * c0 / U, 1000 * c0 / U, true);          // c1_b
      add(0.1 * F / X, F / X, 0.0, 100 * F / X, false);                    // k0
      add(0.01 * F / X, F / X, -10 * F / X, 10 * F / X, false);            // k1
      add(gamma, gamma, 0.0, 1000 * gamma, false);                         // gamma
      add(gamma, gamma, 0.0, 1000 * gamma, false);                         // beta
      add(A, A, A, A, false);                                              // A (scale of z)
      add(190.0, 190.0, 1.0, 5000.0, true);                                // eta
      add(ymean, F, ymean - 10 * F, ymean + 10 * F, false);                // offset
      g.fixed[lumped::pheno_param_index(kind, "A")] =
          true;  // z's scale is not identifiable with alpha
      break;
    }
    case lumped::PhenoKind::maxwell:
      add(0.015, 0.015, 1e-5, 2.0, false);
      add(0.3 * F / M, F / M, 0.0, 100 * F / M, false);
      add(0.5 * F, F, 0.0, 10 * F, false);
      add(0.0, F / U, -10 * F / U, 10 * F / U, true);
      add(3.0 / M, 3.0 / M, 0.01 / M, 1000 / M, false);
      add(ymean, F, ymean - 10 * F, ymean + 10 * F, false);
      break;
    case lumped::PhenoKind::dahl:
      add(0.3 * F / M, F / M, 0.0, 100 * F / M, false);
      add(0.5 * F, F, 0.0, 10 * F, false);
      add(0.0, F / U, -10 * F / U, 10 * F / U, true);
      add(10.0 / X, 10.0 / X, 0.01 / X, 1e4 / X, false);
      add(0.0, F / X, -10 * F / X, 10 * F / X, false);
      add(ymean, F, ymean - 10 * F, ymean + 10 * F, false);
      break;
    case lumped::PhenoKind::biviscous:
      add(0.5 * F, F, 0.0, 10 * F, false);                                 // yield
      add(0.0, F / U, -10 * F / U, 10 * F / U, true);                      // yield_per_field
      add(0.5 * F / M, F / M, 0.0, 100 * F / M, false);                    // post_yield
      add(0.0, F / (M * U), -100 * F / (M * U), 100 * F / (M * U), true);  // post_yield_per_field
      add(20 * F / M, 20 * F / M, F / M, 1e4 * F / M, false);              // pre_yield
      add(ymean, F, ymean - 10 * F, ymean + 10 * F, false);                // offset
      break;
    case lumped::PhenoKind::tanh:
      add(0.3 * F / M, F / M, 0.0, 100 * F / M, false);                    // viscous
      add(0.0, F / (M * U), -100 * F / (M * U), 100 * F / (M * U), true);  // viscous_per_field
      add(0.0, F / X, -10 * F / X, 10 * F / X, false);                     // stiffness
      add(0.5 * F, F, 0.0, 10 * F, false);                                 // hysteretic
      add(0.0, F / U, -10 * F / U, 10 * F / U, true);                      // hysteretic_per_field
      add(3.0 / M, 3.0 / M, 0.01 / M, 1000 / M, false);                    // shape
      add(0.3, 1.0, -5.0, 5.0, false);                                     // lag
      add(ymean, F, ymean - 10 * F, ymean + 10 * F, false);                // offset
      break;
    case lumped::PhenoKind::damper:
      add(0.3 * F, F, 0.0, 10 * F, false);                                 // yield
      add(0.3 * F / U, F / U, -10 * F / U, 10 * F / U, true);              // yield_per_field
      add(0.0, F / (U * U), -10 * F / (U * U), 10 * F / (U * U), true);    // ..._per_field2
      add(0.3 * F / M, F / M, 1e-3 * F / M, 100 * F / M, false);           // consistency
      add(0.0, F / (M * U), -100 * F / (M * U), 100 * F / (M * U), true);  // ..._per_field
      add(1.0, 1.0, 0.2, 2.0, false);                                      // flow_index
      add(30 * F / M, 30 * F / M, F / M, 1e5 * F / M, false);              // pre_yield_viscous
      add(20 * F / X, 20 * F / X, 0.1 * F / X, 1e4 * F / X, false);        // compliance_stiffness
      add(0.0, 1.0 / X, 0.0, 1e3 / X, false);                              // stiffening
      add(0.05 * F, F, 0.0, 2 * F, false);                                 // seal_friction
      add(0.0, F / U, 0.0, 2 * F / U, true);                               // ..._per_field
      add(0.01 * X, 0.01 * X, 1e-5 * X, X, false);                         // seal_presliding
      add(0.0, F / Acc, -10 * F / Acc, 10 * F / Acc, false);               // inertance
      add(0.0, F / X, -10 * F / X, 10 * F / X, false);                     // gas_stiffness
      add(0.01, 0.01, 1e-4, 1.0, true);                                    // field_time_constant
      add(ymean, F, ymean - 10 * F, ymean + 10 * F, false);                // offset
      add(0.0, 1.0 / (U * U), 0.0, 100.0 / (U * U), true);                 // field_saturation
      // The saturation is identifiable only with more field levels than the quadratic F_y(b) has
      // coefficients (3): with fewer, F_y passes through every level for any saturation.
      if (has_field && field_levels(d, r, 4) < 4) {
        g.nominal.back() = 0.0;
        g.fixed.back() = true;
      }
      if (!has_field)
        g.nominal[lumped::pheno_param_index(kind, "field_time_constant")] = 0.01;  // held
      break;
  }
  // output_smoothing, the last parameter of every model: held at 0 without a drive period to
  // measure the window against.
  add(0.05, 0.1, 0.0, 0.25, false);
  if (!periodic) {
    g.nominal.back() = 0.0;
    g.fixed.back() = true;
  }
  return g;
}

/// run_fit<N, NF> for the free-parameter count `nf` of `guess`, NF one of the listed counts (the
/// model's parameters with and without its field terms). A count that is not listed (parameters
/// held by GreyboxOptions::held) runs in the next larger one, with that many held parameters
/// pinned in free slots (ParamGuess::pinned): the same fit, without an instantiation per count.
template <int N, int... NF>
void run_fit_free(const FitData& data, const lumped::GreyboxSetup& setup, const ParamGuess& guess,
                  const GreyboxOptions& options, GreyboxFit& fit) {
  const int nf = static_cast<int>(std::count(guess.fixed.begin(), guess.fixed.end(), false));
  int slots = N + 1;  // the smallest listed count >= nf
  ((NF >= nf && NF < slots ? (slots = NF, 0) : 0), ...);
  if (slots > N)
    throw std::logic_error("grey-box fit of " + fit.model + ": unexpected free-parameter count " +
                           std::to_string(nf));
  ParamGuess slotted = guess;
  int to_pin = slots - nf;
  if (to_pin > 0) {
    slotted.pinned.assign(guess.fixed.size(), false);
    for (std::size_t k = 0; k < guess.fixed.size() && to_pin > 0; ++k)
      if (guess.fixed[k]) {
        slotted.fixed[k] = false;
        slotted.pinned[k] = true;
        --to_pin;
      }
  }
  const bool ran =
      ((slots == NF ? (run_fit<N, NF>(data, setup, slotted, options, fit), true) : false) || ...);
  if (!ran)
    throw std::logic_error("grey-box fit of " + fit.model + ": unexpected free-parameter count " +
                           std::to_string(nf));
}

/// Holds the parameters `held` names at their values in `guess` (GreyboxOptions::held). InputError
/// naming `where` for a name the model does not have, a value outside the parameter's bounds, a
/// parameter held twice, or no parameter left to fit.
void apply_holds(lumped::PhenoKind kind, const std::string& model,
                 const std::vector<std::pair<std::string, double>>& held, const std::string& where,
                 ParamGuess& guess) {
  const auto& specs = lumped::pheno_params(kind);
  std::vector<bool> seen(specs.size(), false);
  for (const auto& [name, value] : held) {
    const int k = lumped::pheno_param_index(kind, name);
    if (k < 0) {
      std::string names;
      for (const auto& p : specs) names += (names.empty() ? "" : ", ") + p.name;
      throw InputError(where + ": held parameter '" + name + "': the " + model +
                       " model has no such parameter (expected one of " + names + ")");
    }
    const auto i = static_cast<std::size_t>(k);
    if (seen[i]) throw InputError(where + ": parameter '" + name + "' is held twice");
    seen[i] = true;
    if (!std::isfinite(value) || value < guess.lower[i] || value > guess.upper[i])
      throw InputError(
          format_text("%s: held parameter '%s' = %g: expected a value within its "
                      "bounds [%g, %g] for these recordings (SI units)",
                      where.c_str(), name.c_str(), value, guess.lower[i], guess.upper[i]));
    guess.nominal[i] = value;
    guess.fixed[i] = true;
  }
  if (std::none_of(guess.fixed.begin(), guess.fixed.end(), [](bool f) { return !f; }))
    throw InputError(where + ": every parameter of the " + model +
                     " model is held; expected at least one to fit");
}

lumped::PhenoKind parse_model(const std::string& model) {
  lumped::PhenoKind kind;
  if (!lumped::parse_pheno_kind(model, kind)) {
    std::string names;
    for (const std::string& n : greybox_model_names()) names += (names.empty() ? "" : ", ") + n;
    throw InputError("unknown grey-box model '" + model + "' (expected one of " + names + ")");
  }
  return kind;
}

/// All series of `data` end to end (for magnitudes and orientation only: the time base is dropped)
/// with the range covering everything.
lumped::DriveSeries concatenated(const FitData& data, lumped::SampleRange& range) {
  lumped::DriveSeries all;
  for (std::size_t r = 0; r < data.series.size(); ++r) {
    const lumped::DriveSeries& d = data.series[r];
    const lumped::SampleRange& k = data.ranges[r];
    const auto append = [&](std::vector<double>& to, const std::vector<double>& from) {
      to.insert(to.end(), from.begin() + static_cast<std::ptrdiff_t>(k.begin),
                from.begin() + static_cast<std::ptrdiff_t>(k.end));
    };
    append(all.position, d.position);
    append(all.motion, d.motion);
    append(all.field, d.field);
    append(all.acceleration, d.acceleration);
    append(all.y, d.y);
  }
  range = lumped::SampleRange{0, all.y.size()};
  return all;
}

/// Runs the multi-start fit of `guess` (its held parameters applied) with the free-parameter count
/// instantiated for fit.setup.kind.
void run_model_fit(const FitData& data, const ParamGuess& guess, const GreyboxOptions& options,
                   GreyboxFit& fit) {
  switch (fit.setup.kind) {  // free counts with and without a field input
    // with and without output_smoothing (held without a periodic drive)
    case lumped::PhenoKind::bingham:
    case lumped::PhenoKind::biviscous:
      run_fit_free<7, 7, 6, 5, 4>(data, fit.setup, guess, options, fit);
      break;
    case lumped::PhenoKind::maxwell:
    case lumped::PhenoKind::dahl:
      run_fit_free<7, 7, 6, 5>(data, fit.setup, guess, options, fit);
      break;
    case lumped::PhenoKind::lugre:
    case lumped::PhenoKind::tanh:
      run_fit_free<9, 9, 8, 7, 6>(data, fit.setup, guess, options, fit);
      break;
    case lumped::PhenoKind::bouc_wen:
      run_fit_free<14, 13, 12, 9, 8>(data, fit.setup, guess, options, fit);
      break;
    case lumped::PhenoKind::damper:
      run_fit_free<18, 18, 17, 16, 12, 11>(data, fit.setup, guess, options, fit);
      break;
  }
}

/// Whether a fit of `kind` with `options` checks that its inertance is seen (the damper model,
/// the inertance not held by the user, the check on).
bool checks_inertance(lumped::PhenoKind kind, const GreyboxOptions& options) {
  if (kind != lumped::PhenoKind::damper || !(options.min_inertance_gain > 0.0) ||
      options.inertance_check_iterations <= 0)
    return false;
  return std::none_of(options.held.begin(), options.held.end(),
                      [](const auto& h) { return h.first == "inertance"; });
}

/// Refits `fit` with its inertance held at 0 (one start from the fit, the check's iterations) and
/// keeps that refit when the fitted inertance removed less than options.min_inertance_gain of
/// its residual energy: on drives whose accelerations are small (slow sines) the inertance
/// otherwise takes up test-to-test differences and runs away when the model is driven faster.
/// Records the share either way (fit.inertance_gain). `fit_bound`: the iterations counted before.
void hold_unseen_inertance(const FitData& data, ParamGuess guess, const GreyboxOptions& options,
                           int fit_bound, GreyboxFit& fit) {
  const auto k = static_cast<std::size_t>(lumped::pheno_param_index(fit.setup.kind, "inertance"));
  if (guess.fixed[k]) return;
  GreyboxOptions check = options;
  check.start.clear();
  for (const FittedParameter& p : fit.params) check.start.push_back(p.value);
  check.starts = 1;
  check.max_iterations = options.inertance_check_iterations;
  if (options.progress)
    check.progress = [&](const ProgressEvent& e) {
      ProgressEvent counted = e;
      counted.stage = "checking that the inertance is seen";
      counted.done = fit_bound + e.done;
      counted.total = fit_bound + options.inertance_check_iterations;
      options.progress(counted);
    };
  guess.nominal[k] = 0.0;
  guess.fixed[k] = true;
  GreyboxFit held = fit;
  held.starts_run = 0;
  try {
    run_model_fit(data, guess, check, held);
  } catch (const ConvergenceError&) {
    return;  // no finite simulation without it: the fit keeps its inertance, unchecked
  }
  const double gain = held.cost > 0.0 ? 1.0 - fit.cost / held.cost : 0.0;
  fit.inertance_gain = gain;
  if (!(gain < options.min_inertance_gain)) return;
  held.inertance_gain = gain;
  held.starts_run += fit.starts_run;
  held.params[k].held_because = format_text(
      "at 0: fitted, it removed %.1f %% of the residual energy (under %.0f %%), a "
      "moving mass these drives do not show",
      100.0 * std::max(gain, 0.0), 100.0 * options.min_inertance_gain);
  fit = std::move(held);
}

/// Where training series are tared at their rest, sets the offset's reference
/// (PhenoSettings::rest_reference) to their mean level at rest and starts the offset there: the
/// start is the plain tare, and the fit moves the level in motion away from it where the model
/// asks. NaN where no series is tared.
void set_rest_reference(const FitData& data, lumped::GreyboxSetup& setup, ParamGuess& guess) {
  double sum = 0.0;
  std::size_t tared = 0;
  for (std::size_t r = 0; r < data.series.size(); ++r) {
    const lumped::DriveSeries& s = data.series[r];
    if (s.mean_removed || s.rest_samples == 0 || data.ranges[r].begin != 0 ||
        data.ranges[r].end <= s.rest_samples)
      continue;
    sum += s.rest_level;
    ++tared;
  }
  setup.settings.rest_reference = std::numeric_limits<double>::quiet_NaN();
  const int k = lumped::pheno_param_index(setup.kind, "offset");
  if (tared == 0 || k < 0) return;
  const double reference = setup.orientation * sum / static_cast<double>(tared);
  setup.settings.rest_reference = reference;
  const auto i = static_cast<std::size_t>(k);
  guess.nominal[i] = std::clamp(reference, guess.lower[i], guess.upper[i]);
}

/// Fits `fit.setup` (kind and columns set) to `data`: orientation, regularisation widths, guess,
/// multi-start Ceres fit; fills fit.params and the start counters. `where` names the data.
void fit_data(const FitData& data, const GreyboxOptions& options, const std::string& where,
              GreyboxFit& fit) {
  const lumped::PhenoKind kind = fit.setup.kind;
  lumped::SampleRange range;
  const lumped::DriveSeries all = concatenated(data, range);
  // Orientation: make the output grow with the motion (mrdamper's force has the opposite sign).
  double corr = 0.0;
  for (std::size_t i = 0; i < range.end; ++i) corr += all.y[i] * all.motion[i];
  fit.setup.orientation = corr < 0.0 ? -1.0 : 1.0;
  const double m_rms = lumped::rms_on(all.motion, range);
  if (!(m_rms > 0.0)) throw InputError(where + ": the motion drive is zero throughout");
  fit.setup.settings.eps = options.eps_fraction * m_rms;
  fit.setup.settings.motion_scale = m_rms;
  fit.setup.settings.position_scale = std::max(lumped::rms_on(all.position, range), 1e-300);
  double y_max = 0.0;
  for (double y : all.y) y_max = std::max(y_max, std::abs(y));
  if (!(y_max > 0.0)) throw InputError(where + ": the output is zero on the training samples");
  fit.setup.settings.output_scale = y_max;
  const bool periodic = std::any_of(data.series.begin(), data.series.end(),
                                    [](const lumped::DriveSeries& d) { return d.period > 0.0; });
  const std::size_t n_params = lumped::pheno_params(kind).size();
  if (!options.start.empty() && options.start.size() != n_params)
    throw InputError(where + ": the start of the " + fit.model + " fit has " +
                     std::to_string(options.start.size()) +
                     " values; expected one per parameter (" + std::to_string(n_params) + ")");
  ParamGuess guess = initial_guess(kind, all, range, fit.setup.orientation,
                                   !fit.setup.field_column.empty(), periodic);
  set_rest_reference(data, fit.setup, guess);
  apply_holds(kind, fit.model, options.held, where, guess);
  if (!checks_inertance(kind, options)) {
    run_model_fit(data, guess, options, fit);
    return;
  }
  // The fit counts its iterations against a bound that includes the inertance check's.
  const int fit_bound = std::max(1, options.starts) * options.max_iterations;
  const int bound = fit_bound + options.inertance_check_iterations;
  GreyboxOptions first = options;
  if (options.progress)
    first.progress = [&](const ProgressEvent& e) {
      ProgressEvent counted = e;
      counted.total = bound;
      options.progress(counted);
    };
  run_model_fit(data, guess, first, fit);
  hold_unseen_inertance(data, guess, options, fit_bound, fit);
}

std::vector<double> param_values(const GreyboxFit& fit) {
  std::vector<double> values;
  for (const auto& p : fit.params) values.push_back(p.value);
  return values;
}

/// Where every training series is fitted whole and compared without its level (its output's mean
/// removed), the offset is not identified by the fit and its value is whatever the optimiser
/// left. Sets it so that the model's raw output has zero mean over the recordings, as they do (a
/// model saved and run elsewhere then keeps their level); nothing any comparison with these
/// recordings sees changes. (A tared series sees the offset through PhenoSettings::rest_reference.)
void centre_unidentified_offset(const FitData& data, GreyboxFit& fit, double max_substep) {
  for (std::size_t r = 0; r < data.series.size(); ++r) {
    const lumped::DriveSeries& s = data.series[r];
    if (!s.mean_removed || data.ranges[r].begin != 0 || data.ranges[r].end != s.t.size()) return;
  }
  const int k = lumped::pheno_param_index(fit.setup.kind, "offset");
  if (k < 0 || fit.params[static_cast<std::size_t>(k)].fixed) return;
  // The level wanted minus the raw model's level, weighted by the samples it is taken over.
  double shift = 0.0, weight = 0.0;
  for (const lumped::DriveSeries& series : data.series) {
    lumped::DriveSeries raw = series;
    raw.mean_removed = false;  // the model's own level, neither removed nor tared
    raw.rest_samples = 0;
    const std::vector<double> y =
        lumped::simulate_for_report(raw, fit.setup, param_values(fit), max_substep);
    const std::size_t n = y.size();
    const double level = std::accumulate(y.begin(), y.end(), 0.0) / static_cast<double>(n);
    shift -= static_cast<double>(n) * level;
    weight += static_cast<double>(n);
  }
  // The output is orientation x (model + offset): shifting the offset by shift/orientation moves
  // the raw output by shift.
  fit.params[static_cast<std::size_t>(k)].value += shift / weight / fit.setup.orientation;
}

/// Damper model: raises the highest fitted field level (PhenoSettings::field_high) to the field
/// column's largest value over samples [begin, end) of `rec`, so that the model, run later on a
/// field above it, continues its yield along its tangent. Other models: nothing.
void widen_fitted_field(GreyboxFit& fit, const lumped::Recording& rec, std::size_t begin,
                        std::size_t end) {
  if (fit.setup.kind != lumped::PhenoKind::damper || fit.setup.field_column.empty()) return;
  const std::vector<double>& u = rec.column(fit.setup.field_column);
  end = std::min(end, u.size());
  if (begin >= end) return;
  const double hi = *std::max_element(u.begin() + static_cast<std::ptrdiff_t>(begin),
                                      u.begin() + static_cast<std::ptrdiff_t>(end));
  double& high = fit.setup.settings.field_high;
  high = std::isfinite(high) ? std::max(high, hi) : hi;
}

}  // namespace

std::string parameter_remark(const FittedParameter& p) {
  if (p.fixed) return p.held_because.empty() ? "held" : "held " + p.held_because;
  if (p.at_bound) return "at bound";
  if (!p.standard_error || !std::isfinite(*p.standard_error)) return "not identified";
  if (*p.standard_error > kPoorlyIdentifiedRelativeError * std::abs(p.value)) {
    char text[80];
    if (p.value == 0.0)
      std::snprintf(text, sizeof text, "poorly identified (s.e. %.2g, value 0)", *p.standard_error);
    else
      std::snprintf(text, sizeof text, "poorly identified (s.e. %.2g x |value|)",
                    *p.standard_error / std::abs(p.value));
    return text;
  }
  return "";
}

std::optional<double> level_in_motion_above_rest(const GreyboxFit& fit) {
  const int k = lumped::pheno_param_index(fit.setup.kind, "offset");
  const double reference = fit.setup.settings.rest_reference;
  if (k < 0 || !std::isfinite(reference) || static_cast<std::size_t>(k) >= fit.params.size())
    return std::nullopt;
  return fit.setup.orientation * (fit.params[static_cast<std::size_t>(k)].value - reference);
}

const std::vector<std::string>& greybox_model_names() {
  static const std::vector<std::string> names = {"bingham", "lugre",      "bouc-wen", "maxwell",
                                                 "dahl",    "bi-viscous", "tanh",     "damper"};
  return names;
}

int greybox_iteration_bound(const std::string& model, const GreyboxOptions& options) {
  const int fit = std::max(1, options.starts) * options.max_iterations;
  return checks_inertance(parse_model(model), options) ? fit + options.inertance_check_iterations
                                                       : fit;
}

bool is_greybox_model(const std::string& model) {
  lumped::PhenoKind kind;
  return lumped::parse_pheno_kind(model, kind);
}

GreyboxFit fit_greybox(const lumped::Recording& rec, const std::string& model,
                       const GreyboxOptions& options) {
  const lumped::PhenoKind kind = parse_model(model);
  FLAGS_minloglevel = 3;  // Ceres logs failed trial steps through glog; results are reported here
  GreyboxFit fit;
  fit.model = lumped::pheno_name(kind);
  fit.setup = lumped::greybox_setup_for(rec, kind);
  fit.setup.motion_lead = options.motion_lead;
  FitData data;
  data.series.push_back(lumped::drive_series(rec, fit.setup));
  const lumped::DriveSeries& d = data.series.front();
  const lumped::SampleRange range = options.train.value_or(lumped::SampleRange{0, d.t.size()});
  if (range.end > d.t.size() || range.begin >= range.end)
    throw InputError(rec.csv_path + ": training range " + std::to_string(range.begin) + ":" +
                     std::to_string(range.end) + " is outside the " + std::to_string(d.t.size()) +
                     " samples");
  const std::size_t min_samples = 4 * lumped::pheno_params(kind).size();
  if (range.size() < min_samples)
    throw InputError(rec.csv_path + ": model " + fit.model + " needs at least " +
                     std::to_string(min_samples) + " training samples, got " +
                     std::to_string(range.size()));
  fit.train_range = range;
  // Training that starts after the rest is simulated from its own first sample, so it cannot be
  // tared; the run over the whole recording then keeps the level the fit found, untared too.
  if (range.begin != 0) data.series.front().rest_samples = 0;
  if (const std::size_t rest = d.rest_samples; rest > 0)
    fit.tared_rest_seconds = d.t[rest] - d.t[0];
  data.ranges.push_back(range);
  double y_scale = 0.0;
  for (std::size_t i = range.begin; i < range.end; ++i)
    y_scale = std::max(y_scale, std::abs(d.y[i]));
  data.y_scales.push_back(y_scale);
  fit_data(data, options, rec.csv_path, fit);
  centre_unidentified_offset(data, fit, options.max_substep);
  widen_fitted_field(fit, rec, range.begin, range.end);
  fit.simulated = lumped::simulate_for_report(d, fit.setup, param_values(fit), options.max_substep);
  fit.train = lumped::compute_metrics(d.y, fit.simulated, range);
  fit.residual_sigma = rms_residual(d.y, fit.simulated, range);
  return fit;
}

GreyboxFit fit_greybox_family(const std::vector<lumped::Recording>& recs, const std::string& model,
                              const GreyboxOptions& options, int decimation) {
  const lumped::PhenoKind kind = parse_model(model);
  if (recs.empty()) throw InputError("grey-box family fit: no recordings given");
  if (decimation < 1)
    throw InputError("decimation must be at least 1, got " + std::to_string(decimation));
  FLAGS_minloglevel = 3;
  GreyboxFit fit;
  fit.model = lumped::pheno_name(kind);
  fit.setup = lumped::greybox_setup_for(recs.front(), kind);
  fit.setup.motion_lead = options.motion_lead;
  FitData data;
  for (const lumped::Recording& rec : recs) {
    const lumped::GreyboxSetup setup = lumped::greybox_setup_for(rec, kind);
    if (setup.motion_column != fit.setup.motion_column ||
        setup.position_column != fit.setup.position_column ||
        setup.field_column != fit.setup.field_column ||
        setup.output_column != fit.setup.output_column)
      throw InputError(rec.csv_path + ": drive/output columns differ from " +
                       recs.front().csv_path + "; a family fit needs recordings of the same kind");
    lumped::DriveSeries d =
        lumped::drive_series(rec, fit.setup, static_cast<std::size_t>(decimation));
    const std::size_t n = d.t.size();
    if (n < 4 * lumped::pheno_params(kind).size())
      throw InputError(rec.csv_path + ": too few samples for model " + fit.model + " (" +
                       std::to_string(n) + " after decimation " + std::to_string(decimation) + ")");
    // Every recording weighs the same: its residuals are scaled by its own spread, so the cost is
    // the sum over recordings of (1 - FIT)^2 / 2.
    double mean = std::accumulate(d.y.begin(), d.y.end(), 0.0) / static_cast<double>(n);
    double ss = 0.0;
    for (double y : d.y) ss += (y - mean) * (y - mean);
    if (!(ss > 0.0)) throw InputError(rec.csv_path + ": the output is constant");
    data.ranges.push_back(lumped::SampleRange{0, n});
    data.y_scales.push_back(std::sqrt(ss));
    data.series.push_back(std::move(d));
  }
  if (!options.viscous_factors.empty() && options.viscous_factors.size() != recs.size())
    throw InputError("grey-box family fit: " + std::to_string(options.viscous_factors.size()) +
                     " viscosity factors for " + std::to_string(recs.size()) + " recordings");
  data.viscous_factors = options.viscous_factors;
  fit_data(data, options, recs.front().csv_path, fit);
  centre_unidentified_offset(data, fit, options.max_substep);
  for (const lumped::Recording& rec : recs) widen_fitted_field(fit, rec, 0, rec.t.size());
  fit.train_range = lumped::SampleRange{0, 0};
  return fit;
}

std::vector<double> simulate_greybox(const lumped::Recording& rec, const GreyboxFit& fit) {
  lumped::GreyboxSetup setup = lumped::greybox_setup_for(rec, fit.setup.kind);
  if (setup.field_column.empty() != fit.setup.field_column.empty() ||
      setup.motion_column != fit.setup.motion_column ||
      setup.output_column != fit.setup.output_column)
    throw InputError(rec.csv_path + ": drive/output columns differ from the recording the " +
                     fit.model + " model was fitted on");
  setup.orientation = fit.setup.orientation;
  setup.settings = fit.setup.settings;
  setup.motion_lead = fit.setup.motion_lead;
  return lumped::simulate_pheno(rec, setup, param_values(fit));
}

}  // namespace rheomag::identify
