// Grey-box fits: Ceres Levenberg-Marquardt with bounds on normalised parameters, residuals from a
// fixed-step RK4 free-run simulation differentiated by Jets; reported output from rosenbrock4.

#include "lumped/greybox.hpp"

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>

#include "core/error.hpp"
#include "lumped/multistart_fit.hpp"
#include "lumped/ode.hpp"
#include "lumped/output_smoothing.hpp"
#include "lumped/standard_errors.hpp"

namespace rheomag::lumped {

namespace {

/// Drive and output samples of one recording as a model sees them.
struct DriveSeries {
  std::vector<double> t, position, motion, field, acceleration, y;
  double period = 0.0;        ///< [s] period of a periodic motion drive, else 0 (drive_period)
  bool mean_removed = false;  ///< the recording's output had its mean removed (output_mean_removed)
  PhenoDrive at(std::size_t i) const { return {position[i], motion[i], field[i], acceleration[i]}; }
  /// Linear interpolation between sample i and i+1 at fraction w in [0, 1].
  PhenoDrive between(std::size_t i, double w) const {
    return {position[i] + w * (position[i + 1] - position[i]),
            motion[i] + w * (motion[i + 1] - motion[i]), field[i] + w * (field[i + 1] - field[i]),
            acceleration[i] + w * (acceleration[i + 1] - acceleration[i])};
  }
};

/// Every `step`-th sample of `v`.
std::vector<double> every(const std::vector<double>& v, std::size_t step) {
  std::vector<double> out;
  for (std::size_t i = 0; i < v.size(); i += step) out.push_back(v[i]);
  return out;
}

/// Rate of `v` on the time base `t`: central differences inside, one-sided at the ends.
std::vector<double> rate_of(const std::vector<double>& t, const std::vector<double>& v) {
  std::vector<double> r(v.size(), 0.0);
  if (v.size() < 2) return r;
  for (std::size_t i = 1; i + 1 < v.size(); ++i)
    r[i] = (v[i + 1] - v[i - 1]) / (t[i + 1] - t[i - 1]);
  r.front() = (v[1] - v[0]) / (t[1] - t[0]);
  r.back() = (v[v.size() - 1] - v[v.size() - 2]) / (t[v.size() - 1] - t[v.size() - 2]);
  return r;
}

/// The drive and output of `rec` as `setup` reads them, keeping every `step`-th sample.
DriveSeries drive_series(const Recording& rec, const GreyboxSetup& setup, std::size_t step = 1) {
  DriveSeries d;
  d.t = every(rec.t, step);
  d.motion = every(rec.column(setup.motion_column), step);
  d.y = every(rec.column(setup.output_column), step);
  d.field = setup.field_column.empty() ? std::vector<double>(d.t.size(), 0.0)
                                       : every(rec.column(setup.field_column), step);
  d.acceleration = rate_of(d.t, d.motion);
  d.period = drive_period(d.t, d.motion);
  d.mean_removed = output_mean_removed(rec.column(setup.output_column));
  if (!setup.position_column.empty()) {
    d.position = every(rec.column(setup.position_column), step);
  } else {
    // Trapezoidal integral of the motion, mean removed (the absolute position is unknown).
    d.position.assign(d.t.size(), 0.0);
    for (std::size_t i = 1; i < d.t.size(); ++i)
      d.position[i] =
          d.position[i - 1] + 0.5 * (d.motion[i] + d.motion[i - 1]) * (d.t[i] - d.t[i - 1]);
    double mean = std::accumulate(d.position.begin(), d.position.end(), 0.0) /
                  static_cast<double>(d.position.size());
    for (double& x : d.position) x -= mean;
  }
  return d;
}

/// Largest |df_k/dx_k| at state x (forward differences on the values): the stiffest rate, used to
/// keep the explicit RK4 step inside its stability region (h |lambda| <= 2).
template <class T>
double stiffest_rate(PhenoKind kind, const T* p, const PhenoDrive& d, const PhenoSettings& s,
                     const T* x, std::size_t n) {
  constexpr std::size_t kMaxStates = 3;
  std::array<double, 16> pv{};
  const std::size_t np = pheno_params(kind).size();
  for (std::size_t k = 0; k < np; ++k) pv[k] = value_of(p[k]);
  std::array<double, kMaxStates> xv{}, f0{}, f1{};
  for (std::size_t k = 0; k < n; ++k) xv[k] = value_of(x[k]);
  pheno_derivatives(kind, pv.data(), d, s, xv.data(), f0.data());
  double rate = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double h = 1e-6 * std::max(std::abs(xv[k]), 1e-6);
    xv[k] += h;
    pheno_derivatives(kind, pv.data(), d, s, xv.data(), f1.data());
    xv[k] -= h;
    rate = std::max(rate, std::abs(f1[k] - f0[k]) / h);
  }
  return rate;
}

/// A model's output seen through the recording's processing: a centred moving average over
/// output_smoothing (the model's last parameter) times the drive's period (nothing without a
/// periodic drive), then, if the recording's output had its mean removed and `range` is the whole
/// recording, the output's own mean removed.
template <class T>
void process_output(PhenoKind kind, const T* p, const DriveSeries& d, SampleRange range, T* out) {
  if (d.period > 0.0)
    centred_boxcar(&d.t[range.begin], range.size(), T(p[pheno_smoothing_index(kind)] * d.period),
                   out);
  if (d.mean_removed && range.begin == 0 && range.end == d.t.size()) remove_mean(out, range.size());
}

/// Models integrated by their own stiff-stable exponential step (damper_step, bouc_wen_step).
bool has_exponential_step(PhenoKind kind) {
  return kind == PhenoKind::damper || kind == PhenoKind::bouc_wen;
}

/// One exponential midpoint step of the damper or Bouc-Wen model (damper_step, bouc_wen_step).
/// Flattened, i.e. every Jet operation inside inlined: GCC left the 12-15-lane Jet additions and
/// products out of line, which was half of a fit's time; the arithmetic is the same.
template <class T>
[[gnu::flatten]] void exponential_step(PhenoKind kind, const T* p, const PhenoDrive& start,
                                       const PhenoDrive& middle, const PhenoSettings& s, double h,
                                       BoucWenFieldGains<T>& gains, T* x) {
  if (kind == PhenoKind::damper)
    damper_step(p, start, middle, s, h, x);
  else
    bouc_wen_step(p, start, middle, s, h, gains, x);
}

/// Free-run simulation of samples [begin, end): RK4 with substeps no longer than max_substep and
/// short enough for the stiffest rate (the damper and Bouc-Wen models: exponential midpoint steps
/// no longer than max_substep, see damper_step and bouc_wen_step). Returns false if the state
/// became non-finite.
template <class T>
bool simulate_rk4(PhenoKind kind, const T* p, const DriveSeries& d, const PhenoSettings& s,
                  std::size_t begin, std::size_t end, double max_substep, T* out) {
  constexpr std::size_t kMaxStates = 3;
  const std::size_t n = pheno_state_count(kind);
  std::array<T, kMaxStates> x, k1, k2, k3, k4, tmp;
  pheno_initial_state(kind, p, d.at(begin), s, x.data());
  out[0] = pheno_output(kind, p, d.at(begin), s, x.data());
  double rate_previous = 0.0;
  BoucWenFieldGains<T> gains;  // Bouc-Wen's field filter, kept from step to step
  for (std::size_t i = begin; i + 1 < end; ++i) {
    const double dt = d.t[i + 1] - d.t[i];
    if (has_exponential_step(kind)) {  // stiff-stable exponential steps, no rate limit
      const int steps = std::max(1, static_cast<int>(std::ceil(dt / max_substep)));
      const double h = dt / steps;
      for (int j = 0; j < steps; ++j) {
        const PhenoDrive start = d.between(i, static_cast<double>(j) / steps),
                         middle = d.between(i, (j + 0.5) / steps);
        exponential_step(kind, p, start, middle, s, h, gains, x.data());
      }
      out[i + 1 - begin] = pheno_output(kind, p, d.at(i + 1), s, x.data());
      if (!std::isfinite(value_of(out[i + 1 - begin]))) return false;
      continue;
    }
    // The stiffest rate changes within an interval (hysteretic states saturate), so the larger of
    // this and the previous interval's estimate sets the step.
    const double rate_now = n > 0 ? stiffest_rate(kind, p, d.at(i), s, x.data(), n) : 0.0;
    if (!std::isfinite(rate_now) || rate_now * dt > 2e4) return false;  // hopelessly stiff
    const double rate = std::max(rate_now, rate_previous);
    rate_previous = rate_now;
    const int substeps = std::max({1, static_cast<int>(std::ceil(dt / max_substep)),
                                   static_cast<int>(std::ceil(dt * rate / 2.0))});
    const double h = dt / substeps;
    for (int j = 0; j < substeps && n > 0; ++j) {
      const double w0 = static_cast<double>(j) / substeps,
                   w1 = static_cast<double>(j + 1) / substeps;
      const PhenoDrive da = d.between(i, w0), dm = d.between(i, 0.5 * (w0 + w1)),
                       db = d.between(i, w1);
      pheno_derivatives(kind, p, da, s, x.data(), k1.data());
      for (std::size_t k = 0; k < n; ++k) tmp[k] = x[k] + 0.5 * h * k1[k];
      pheno_derivatives(kind, p, dm, s, tmp.data(), k2.data());
      for (std::size_t k = 0; k < n; ++k) tmp[k] = x[k] + 0.5 * h * k2[k];
      pheno_derivatives(kind, p, dm, s, tmp.data(), k3.data());
      for (std::size_t k = 0; k < n; ++k) tmp[k] = x[k] + h * k3[k];
      pheno_derivatives(kind, p, db, s, tmp.data(), k4.data());
      for (std::size_t k = 0; k < n; ++k)
        x[k] += h / 6.0 * (k1[k] + 2.0 * k2[k] + 2.0 * k3[k] + k4[k]);
    }
    out[i + 1 - begin] = pheno_output(kind, p, d.at(i + 1), s, x.data());
    using std::isfinite;
    if (!std::isfinite(value_of(out[i + 1 - begin]))) return false;
  }
  return true;
}

/// Residuals (model - orientation * measured) / y_scale on a sample range, as a function of the NF
/// free ones of the N normalised parameters (the held ones are constants, so the Jets carry only
/// the free derivatives).
template <int N, int NF>
struct FitResidual {
  const DriveSeries* d;
  PhenoKind kind;
  PhenoSettings settings;
  SampleRange range;
  std::array<double, N> scale;
  std::array<double, N> held;      ///< normalised values of the held parameters
  std::array<int, NF> free_index;  ///< parameter number of each free parameter
  double orientation;
  double y_scale;
  double max_substep;

  template <class T>
  bool operator()(const T* theta, T* residual) const {
    std::array<T, N> p;
    for (int k = 0; k < N; ++k) p[k] = T(held[k] * scale[k]);
    for (int j = 0; j < NF; ++j) p[free_index[j]] = theta[j] * scale[free_index[j]];
    std::vector<T> yhat(range.size());
    if (!simulate_rk4(kind, p.data(), *d, settings, range.begin, range.end, max_substep,
                      yhat.data()))
      return false;
    process_output(kind, p.data(), *d, range, yhat.data());
    for (std::size_t i = 0; i < range.size(); ++i)
      residual[i] = (yhat[i] - orientation * d->y[range.begin + i]) / y_scale;
    return true;
  }
};

/// Nominal value, scale and bounds of each parameter, from the data's magnitudes.
struct ParamGuess {
  std::vector<double> nominal, scale, lower, upper;
  std::vector<bool> fixed;
};

double rms(const std::vector<double>& v, SampleRange r) {
  double s = 0.0;
  for (std::size_t i = r.begin; i < r.end; ++i) s += v[i] * v[i];
  return std::sqrt(s / static_cast<double>(r.size()));
}

/// Number of distinct values the field input takes in `d` on `r`, counted up to `cap`.
std::size_t field_levels(const DriveSeries& d, SampleRange r, std::size_t cap) {
  std::vector<double> levels;
  for (std::size_t i = r.begin; i < r.end && levels.size() < cap; ++i)
    if (std::find(levels.begin(), levels.end(), d.field[i]) == levels.end())
      levels.push_back(d.field[i]);
  return levels.size();
}

ParamGuess initial_guess(PhenoKind kind, const DriveSeries& d, SampleRange r, double orientation,
                         bool has_field, bool periodic) {
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
  const double M = std::max(rms(d.motion, r), 1e-300);
  const double X = std::max(rms(d.position, r), 1e-300);
  const double U = umax > 0.0 ? umax : 1.0;
  const double Acc = std::max(rms(d.acceleration, r), 1e-300);
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
    case PhenoKind::bingham:
      add(0.5 * F, F, 0.0, 10 * F, false);
      add(0.0, F / U, -10 * F / U, 10 * F / U, true);
      add(0.5 * F / M, F / M, 0.0, 100 * F / M, false);
      add(0.0, F / (M * U), -100 * F / (M * U), 100 * F / (M * U), true);
      add(0.1 * M, M, 1e-4 * M, 10 * M, false);
      add(ymean, F, ymean - 10 * F, ymean + 10 * F, false);
      break;
    case PhenoKind::lugre: {
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
    case PhenoKind::bouc_wen: {
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
      g.fixed[pheno_param_index(kind, "A")] = true;  // z's scale is not identifiable with alpha
      break;
    }
    case PhenoKind::maxwell:
      add(0.015, 0.015, 1e-5, 2.0, false);
      add(0.3 * F / M, F / M, 0.0, 100 * F / M, false);
      add(0.5 * F, F, 0.0, 10 * F, false);
      add(0.0, F / U, -10 * F / U, 10 * F / U, true);
      add(3.0 / M, 3.0 / M, 0.01 / M, 1000 / M, false);
      add(ymean, F, ymean - 10 * F, ymean + 10 * F, false);
      break;
    case PhenoKind::dahl:
      add(0.3 * F / M, F / M, 0.0, 100 * F / M, false);
      add(0.5 * F, F, 0.0, 10 * F, false);
      add(0.0, F / U, -10 * F / U, 10 * F / U, true);
      add(10.0 / X, 10.0 / X, 0.01 / X, 1e4 / X, false);
      add(0.0, F / X, -10 * F / X, 10 * F / X, false);
      add(ymean, F, ymean - 10 * F, ymean + 10 * F, false);
      break;
    case PhenoKind::biviscous:
      add(0.5 * F, F, 0.0, 10 * F, false);                                 // yield
      add(0.0, F / U, -10 * F / U, 10 * F / U, true);                      // yield_per_field
      add(0.5 * F / M, F / M, 0.0, 100 * F / M, false);                    // post_yield
      add(0.0, F / (M * U), -100 * F / (M * U), 100 * F / (M * U), true);  // post_yield_per_field
      add(20 * F / M, 20 * F / M, F / M, 1e4 * F / M, false);              // pre_yield
      add(ymean, F, ymean - 10 * F, ymean + 10 * F, false);                // offset
      break;
    case PhenoKind::tanh:
      add(0.3 * F / M, F / M, 0.0, 100 * F / M, false);                    // viscous
      add(0.0, F / (M * U), -100 * F / (M * U), 100 * F / (M * U), true);  // viscous_per_field
      add(0.0, F / X, -10 * F / X, 10 * F / X, false);                     // stiffness
      add(0.5 * F, F, 0.0, 10 * F, false);                                 // hysteretic
      add(0.0, F / U, -10 * F / U, 10 * F / U, true);                      // hysteretic_per_field
      add(3.0 / M, 3.0 / M, 0.01 / M, 1000 / M, false);                    // shape
      add(0.3, 1.0, -5.0, 5.0, false);                                     // lag
      add(ymean, F, ymean - 10 * F, ymean + 10 * F, false);                // offset
      break;
    case PhenoKind::damper:
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
      if (!has_field) g.nominal[pheno_param_index(kind, "field_time_constant")] = 0.01;  // held
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

std::string unit_string(const std::string& pattern, const GreyboxSetup& s) {
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

/// The model as an OdeSystem for the stiff integrator.
class PhenoOde : public OdeSystem {
 public:
  PhenoOde(const GreyboxSetup& setup, const std::vector<double>& p, const DriveSeries& d)
      : setup_(setup), p_(p), d_(d) {}
  std::size_t state_size() const override { return pheno_state_count(setup_.kind); }
  void derivatives(double t, const double* x, double* dxdt) const override {
    pheno_derivatives(setup_.kind, p_.data(), drive_at(t), setup_.settings, x, dxdt);
  }
  std::vector<double> state_scales() const override {
    const SampleRange all{0, d_.t.size()};
    const double X = std::max(rms(d_.position, all), 1e-12);
    switch (setup_.kind) {
      case PhenoKind::bouc_wen:
        return {X, X, std::max(1.0, rms(d_.field, all))};
      case PhenoKind::maxwell:
        return {std::max(rms(d_.y, all), 1.0)};  // [N or Pa]
      case PhenoKind::damper:
        return {std::max(rms(d_.y, all), 1.0), 1.0, std::max(1.0, rms(d_.field, all))};
      default:
        return std::vector<double>(state_size(), 1.0);
    }
  }
  PhenoDrive drive_at(double t) const {
    auto it = std::upper_bound(d_.t.begin(), d_.t.end(), t);
    if (it == d_.t.begin()) return d_.at(0);
    if (it == d_.t.end()) return d_.at(d_.t.size() - 1);
    std::size_t i = static_cast<std::size_t>(it - d_.t.begin()) - 1;
    return d_.between(i, (t - d_.t[i]) / (d_.t[i + 1] - d_.t[i]));
  }

 private:
  const GreyboxSetup& setup_;
  const std::vector<double>& p_;
  const DriveSeries& d_;
};

std::vector<double> simulate_stiff(const DriveSeries& d, const GreyboxSetup& setup,
                                   const std::vector<double>& params) {
  PhenoOde ode(setup, params, d);
  std::vector<double> x0(pheno_state_count(setup.kind));
  pheno_initial_state(setup.kind, params.data(), d.at(0), setup.settings, x0.data());
  IntegratorOptions opt;
  opt.abs_tol = 1e-8;
  opt.rel_tol = 1e-7;
  auto states = integrate_stiff(ode, x0, d.t, opt);
  std::vector<double> y(d.t.size());
  for (std::size_t i = 0; i < y.size(); ++i)
    y[i] = setup.orientation *
           pheno_output(setup.kind, params.data(), d.at(i), setup.settings, states[i].data());
  return y;
}

/// Model output for reports: rosenbrock4; if it gives up (parameters that make the model
/// extremely stiff), the fixed-step RK4 of the fit (stability-limited substeps) is used instead.
std::vector<double> simulate_for_report(const DriveSeries& d, const GreyboxSetup& setup,
                                        const std::vector<double>& params, double max_substep) {
  const auto fixed_step = [&](double step) {
    std::vector<double> y(d.t.size());
    if (!simulate_rk4(setup.kind, params.data(), d, setup.settings, 0, d.t.size(), step, y.data()))
      throw ConvergenceError("model " + pheno_name(setup.kind) +
                             ": the simulation diverges with these parameters");
    for (double& v : y) v *= setup.orientation;
    return y;
  };
  std::vector<double> y;
  if (setup.kind == PhenoKind::damper) {  // its own stiff-stable integrator, at 0.5 ms steps
    y = fixed_step(5e-4);
  } else {
    try {
      y = simulate_stiff(d, setup, params);
    } catch (const ConvergenceError&) {
      y = fixed_step(max_substep);
    }
  }
  process_output(setup.kind, params.data(), d, SampleRange{0, d.t.size()}, y.data());
  return y;
}

/// Longest integration step inside a fit: the damper and Bouc-Wen models' exponential steps are
/// not limited by their stiff modes (only by accuracy), the other models' RK4 substeps are.
double fit_step(PhenoKind kind, const GreyboxOptions& options) {
  if (kind == PhenoKind::bouc_wen) return options.bouc_wen_step;
  return kind == PhenoKind::damper ? options.exponential_step : options.max_substep;
}

/// Reports each Levenberg-Marquardt iteration of a start as progress: the iterations of every
/// start so far out of their bound.
class IterationReport : public ceres::IterationCallback {
 public:
  IterationReport(const ProgressCallback& progress, std::atomic<int>& iterations,
                  std::chrono::steady_clock::time_point start, std::string stage, int bound)
      : progress_(progress),
        iterations_(iterations),
        start_(start),
        stage_(std::move(stage)),
        bound_(bound) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (summary.iteration == 0) return ceres::SOLVER_CONTINUE;  // the starting point
    ProgressEvent e;
    e.stage = stage_;
    e.done = ++iterations_;
    e.total = bound_;
    e.total_is_bound = true;
    e.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    progress_(e);
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const ProgressCallback& progress_;
  std::atomic<int>& iterations_;
  std::chrono::steady_clock::time_point start_;
  std::string stage_;
  int bound_;
};

/// The training data of a fit: one or more drive series, each simulated from its own initial
/// state on its own sample range, its residuals divided by its own scale.
struct FitData {
  std::vector<DriveSeries> series;
  std::vector<SampleRange> ranges;
  std::vector<double> y_scales;
};

/// One multi-start fit of a model with N parameters of which NF are free; fills `fit`.
template <int N, int NF>
void run_fit(const FitData& data, const GreyboxSetup& setup, const ParamGuess& guess,
             const GreyboxOptions& options, GreyboxFit& fit) {
  std::array<int, NF> free{};
  for (int k = 0, j = 0; k < N; ++k)
    if (!guess.fixed[k]) free[j++] = k;
  std::vector<FitResidual<N, NF>> functors;
  for (std::size_t r = 0; r < data.series.size(); ++r) {
    FitResidual<N, NF> functor{&data.series[r],
                               setup.kind,
                               setup.settings,
                               data.ranges[r],
                               {},
                               {},
                               free,
                               setup.orientation,
                               data.y_scales[r],
                               fit_step(setup.kind, options)};
    for (int k = 0; k < N; ++k) {
      functor.scale[k] = guess.scale[k];
      functor.held[k] = guess.nominal[k] / guess.scale[k];
    }
    functors.push_back(functor);
  }

  // Starting points are drawn first, in order, so the result does not depend on which thread
  // finishes first; the starts are independent Ceres problems, solved `threads` at a time.
  std::mt19937 rng(options.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  const int starts = std::max(1, options.starts);
  std::vector<std::array<double, NF>> thetas(static_cast<std::size_t>(starts));
  for (int start = 0; start < starts; ++start) {
    for (int j = 0; j < NF; ++j) {
      const int k = free[j];
      double value = guess.nominal[k];
      if (start > 0) {
        value =
            value != 0.0 ? value * std::exp(0.7 * normal(rng)) : 0.3 * guess.scale[k] * normal(rng);
        const double margin = 1e-6 * (guess.upper[k] - guess.lower[k]);
        value = std::clamp(value, guess.lower[k] + margin, guess.upper[k] - margin);
      }
      thetas[static_cast<std::size_t>(start)][j] = value / guess.scale[k];
    }
  }
  // The starts are independent Ceres problems solved `threads` at a time; threads left over
  // (fewer starts than threads) evaluate a start's residual blocks, one per recording, in parallel.
  const unsigned threads = fit_threads(options.threads);
  const int threads_per_start =
      static_cast<int>(threads / std::min<unsigned>(threads, static_cast<unsigned>(starts)));
  std::vector<ceres::Solver::Summary> summaries(static_cast<std::size_t>(starts));
  std::atomic<int> iterations{0};  // over all starts, for the progress report
  const auto clock_start = std::chrono::steady_clock::now();
  const auto solve_start = [&](std::size_t start) {
    std::array<double, NF>& theta = thetas[start];
    ceres::Problem problem;
    for (const FitResidual<N, NF>& functor : functors)
      problem.AddResidualBlock(
          new CachedCostFunction(
              new ceres::AutoDiffCostFunction<FitResidual<N, NF>, ceres::DYNAMIC, NF>(
                  new FitResidual<N, NF>(functor), static_cast<int>(functor.range.size()))),
          nullptr, theta.data());
    for (int j = 0; j < NF; ++j) {
      problem.SetParameterLowerBound(theta.data(), j, guess.lower[free[j]] / guess.scale[free[j]]);
      problem.SetParameterUpperBound(theta.data(), j, guess.upper[free[j]] / guess.scale[free[j]]);
    }
    ceres::Solver::Options so =
        greybox_solver_options(options.max_iterations, 50);  // trial steps into unstable regions
    so.num_threads = threads_per_start;
    IterationReport report(options.progress, iterations, clock_start, "fitting " + fit.model,
                           starts * options.max_iterations);
    if (options.progress) so.callbacks.push_back(&report);
    ceres::Solve(so, &problem, &summaries[start]);
  };
  for_each_start(static_cast<std::size_t>(starts), threads, solve_start);
  BestStart<NF> best;
  for (int start = 0; start < starts; ++start) {
    ++fit.starts_run;
    best.offer(summaries[static_cast<std::size_t>(start)], thetas[static_cast<std::size_t>(start)],
               start);
  }
  if (!best.found())
    throw ConvergenceError("grey-box fit of " + fit.model +
                           ": no starting point gave a finite simulation");

  // Standard errors: cov = (J^T J)^-1 sigma^2 on the free parameters (normalised), then scaled;
  // the rows of every series stacked.
  int m = 0;
  for (const FitResidual<N, NF>& functor : functors) m += static_cast<int>(functor.range.size());
  Eigen::MatrixXd jf(m, NF);
  Eigen::VectorXd res(m);
  int row = 0;
  for (const FitResidual<N, NF>& functor : functors) {
    const int rows = static_cast<int>(functor.range.size());
    Eigen::Matrix<double, Eigen::Dynamic, NF, Eigen::RowMajor> part_jac;
    Eigen::VectorXd part_res;
    residual_jacobian(functor, rows, best.theta.data(), part_jac, part_res);
    jf.middleRows(row, rows) = part_jac;
    res.segment(row, rows) = part_res;
    row += rows;
  }
  fit.best_start = best.start;
  fit.converged = best.converged;
  const std::vector<std::optional<double>> se = jacobian_standard_errors(jf, res);
  std::vector<int> cluster_rows;
  for (const FitResidual<N, NF>& functor : functors)
    cluster_rows.push_back(static_cast<int>(functor.range.size()));
  const std::optional<ParameterCovariance> between = cluster_covariance(jf, res, cluster_rows);
  const std::vector<std::optional<double>> se_between =
      between ? standard_errors_of(*between) : std::vector<std::optional<double>>(NF);

  const auto& specs = pheno_params(setup.kind);
  fit.params.clear();
  for (int k = 0; k < N; ++k) {
    FittedParameter fp;
    fp.name = specs[k].name;
    fp.unit = unit_string(specs[k].unit, setup);
    fp.value = guess.nominal[k] / guess.scale[k] * guess.scale[k];  // as the simulation sees it
    fp.fixed = guess.fixed[k];
    fit.params.push_back(fp);
  }
  for (int j = 0; j < NF; ++j) {
    const int k = free[j];
    FittedParameter& fp = fit.params[static_cast<std::size_t>(k)];
    fp.value = best.theta[j] * guess.scale[k];
    const double span = guess.upper[k] - guess.lower[k];
    fp.at_bound = std::abs(fp.value - guess.lower[k]) < 1e-6 * span ||
                  std::abs(fp.value - guess.upper[k]) < 1e-6 * span;
    if (se[j]) fp.standard_error = *se[j] * guess.scale[k];
    if (se_between[j]) fp.standard_error_between_recordings = *se_between[j] * guess.scale[k];
  }
  // The covariance between recordings in physical units, over the identifiable free parameters.
  fit.covariance_between_recordings.resize(0, 0);
  if (between) {
    fit.covariance_between_recordings = Eigen::MatrixXd::Zero(N, N);
    for (int a = 0; a < NF; ++a)
      for (int b = 0; b < NF; ++b)
        if (se_between[a] && se_between[b])
          fit.covariance_between_recordings(free[a], free[b]) =
              between->matrix(a, b) * guess.scale[free[a]] * guess.scale[free[b]];
  }
}

/// run_fit<N, NF> for the free-parameter count `nf` of `guess`, NF one of the listed counts (the
/// model's parameters with and without its field terms).
template <int N, int... NF>
void run_fit_free(const FitData& data, const GreyboxSetup& setup, const ParamGuess& guess,
                  const GreyboxOptions& options, GreyboxFit& fit) {
  const int nf = static_cast<int>(std::count(guess.fixed.begin(), guess.fixed.end(), false));
  const bool ran =
      ((nf == NF ? (run_fit<N, NF>(data, setup, guess, options, fit), true) : false) || ...);
  if (!ran)
    throw std::logic_error("grey-box fit of " + fit.model + ": unexpected free-parameter count " +
                           std::to_string(nf));
}

PhenoKind parse_model(const std::string& model) {
  PhenoKind kind;
  if (!parse_pheno_kind(model, kind)) {
    std::string names;
    for (const std::string& n : greybox_model_names()) names += (names.empty() ? "" : ", ") + n;
    throw InputError("unknown grey-box model '" + model + "' (expected one of " + names + ")");
  }
  return kind;
}

/// All series of `data` end to end (for magnitudes and orientation only: the time base is dropped)
/// with the range covering everything.
DriveSeries concatenated(const FitData& data, SampleRange& range) {
  DriveSeries all;
  for (std::size_t r = 0; r < data.series.size(); ++r) {
    const DriveSeries& d = data.series[r];
    const SampleRange& k = data.ranges[r];
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
  range = SampleRange{0, all.y.size()};
  return all;
}

/// Fits `fit.setup` (kind and columns set) to `data`: orientation, regularisation widths, guess,
/// multi-start Ceres fit; fills fit.params and the start counters. `where` names the data.
void fit_data(const FitData& data, const GreyboxOptions& options, const std::string& where,
              GreyboxFit& fit) {
  const PhenoKind kind = fit.setup.kind;
  SampleRange range;
  const DriveSeries all = concatenated(data, range);
  // Orientation: make the output grow with the motion (mrdamper's force has the opposite sign).
  double corr = 0.0;
  for (std::size_t i = 0; i < range.end; ++i) corr += all.y[i] * all.motion[i];
  fit.setup.orientation = corr < 0.0 ? -1.0 : 1.0;
  const double m_rms = rms(all.motion, range);
  if (!(m_rms > 0.0)) throw InputError(where + ": the motion drive is zero throughout");
  fit.setup.settings.eps = options.eps_fraction * m_rms;
  fit.setup.settings.motion_scale = m_rms;
  fit.setup.settings.position_scale = std::max(rms(all.position, range), 1e-300);
  double y_max = 0.0;
  for (double y : all.y) y_max = std::max(y_max, std::abs(y));
  if (!(y_max > 0.0)) throw InputError(where + ": the output is zero on the training samples");
  fit.setup.settings.output_scale = y_max;
  const bool periodic = std::any_of(data.series.begin(), data.series.end(),
                                    [](const DriveSeries& d) { return d.period > 0.0; });
  const ParamGuess guess = initial_guess(kind, all, range, fit.setup.orientation,
                                         !fit.setup.field_column.empty(), periodic);
  switch (kind) {  // free counts with and without a field input
    // with and without output_smoothing (held without a periodic drive)
    case PhenoKind::bingham:
    case PhenoKind::biviscous:
      run_fit_free<7, 7, 6, 5, 4>(data, fit.setup, guess, options, fit);
      break;
    case PhenoKind::maxwell:
    case PhenoKind::dahl:
      run_fit_free<7, 7, 6, 5>(data, fit.setup, guess, options, fit);
      break;
    case PhenoKind::lugre:
    case PhenoKind::tanh:
      run_fit_free<9, 9, 8, 7, 6>(data, fit.setup, guess, options, fit);
      break;
    case PhenoKind::bouc_wen:
      run_fit_free<14, 13, 12, 9, 8>(data, fit.setup, guess, options, fit);
      break;
    case PhenoKind::damper:
      run_fit_free<17, 17, 16, 15, 12, 11>(data, fit.setup, guess, options, fit);
      break;
  }
}

std::vector<double> param_values(const GreyboxFit& fit) {
  std::vector<double> values;
  for (const auto& p : fit.params) values.push_back(p.value);
  return values;
}

/// Where every training series had its output's mean removed and is fitted whole, the model is
/// compared without its mean, so the offset is not identified by the fit and its value is
/// whatever the optimiser left. Sets it so that the model's output has zero mean over the
/// training series, as the recordings do (a model saved and run elsewhere then keeps their level);
/// nothing any comparison with these recordings sees changes.
void centre_unidentified_offset(const FitData& data, GreyboxFit& fit, double max_substep) {
  for (std::size_t r = 0; r < data.series.size(); ++r)
    if (!data.series[r].mean_removed || data.ranges[r].begin != 0 ||
        data.ranges[r].end != data.series[r].t.size())
      return;
  const int k = pheno_param_index(fit.setup.kind, "offset");
  if (k < 0 || fit.params[static_cast<std::size_t>(k)].fixed) return;
  double sum = 0.0, count = 0.0;
  for (const DriveSeries& series : data.series) {
    DriveSeries raw = series;
    raw.mean_removed = false;  // the model's own mean, not removed
    for (double y : simulate_for_report(raw, fit.setup, param_values(fit), max_substep)) sum += y;
    count += static_cast<double>(series.t.size());
  }
  // The output is orientation x (model + offset): shifting the offset by -mean/orientation
  // zeroes the mean.
  fit.params[static_cast<std::size_t>(k)].value -= sum / count / fit.setup.orientation;
}

}  // namespace

const std::vector<std::string>& greybox_model_names() {
  static const std::vector<std::string> names = {"bingham", "lugre",      "bouc-wen", "maxwell",
                                                 "dahl",    "bi-viscous", "tanh",     "damper"};
  return names;
}

bool is_greybox_model(const std::string& model) {
  PhenoKind kind;
  return parse_pheno_kind(model, kind);
}

GreyboxSetup greybox_setup_for(const Recording& rec, PhenoKind kind) {
  GreyboxSetup s;
  s.kind = kind;
  const auto& drive = rec.meta.drive;
  auto driven = [&](const std::string& c) {
    return std::find(drive.begin(), drive.end(), c) != drive.end() && rec.columns.count(c);
  };
  const std::string where = rec.meta.sidecar_path.empty() ? rec.csv_path : rec.meta.sidecar_path;
  if (driven("velocity"))
    s.motion_column = "velocity";
  else if (driven("flow"))
    s.motion_column = "flow";
  else
    throw InputError(where + ": [recording] drive has neither 'velocity' nor 'flow'; model " +
                     pheno_name(kind) + " is driven by motion");
  if (s.motion_column == "velocity" && rec.columns.count("displacement"))
    s.position_column = "displacement";
  for (const char* f : {"command", "current", "current_cmd"})
    if (driven(f)) {
      s.field_column = f;
      break;
    }
  s.output_column = rec.meta.output;
  if (s.output_column != "force" && s.output_column != "pressure")
    throw InputError(where + ": [recording] output '" + s.output_column + "': model " +
                     pheno_name(kind) + " explains 'force' or 'pressure'");
  return s;
}

GreyboxFit fit_greybox(const Recording& rec, const std::string& model,
                       const GreyboxOptions& options) {
  const PhenoKind kind = parse_model(model);
  FLAGS_minloglevel = 3;  // Ceres logs failed trial steps through glog; results are reported here
  GreyboxFit fit;
  fit.model = pheno_name(kind);
  fit.setup = greybox_setup_for(rec, kind);
  FitData data;
  data.series.push_back(drive_series(rec, fit.setup));
  const DriveSeries& d = data.series.front();
  const SampleRange range = options.train.value_or(SampleRange{0, d.t.size()});
  if (range.end > d.t.size() || range.begin >= range.end)
    throw InputError(rec.csv_path + ": training range " + std::to_string(range.begin) + ":" +
                     std::to_string(range.end) + " is outside the " + std::to_string(d.t.size()) +
                     " samples");
  const std::size_t min_samples = 4 * pheno_params(kind).size();
  if (range.size() < min_samples)
    throw InputError(rec.csv_path + ": model " + fit.model + " needs at least " +
                     std::to_string(min_samples) + " training samples, got " +
                     std::to_string(range.size()));
  fit.train_range = range;
  data.ranges.push_back(range);
  double y_scale = 0.0;
  for (std::size_t i = range.begin; i < range.end; ++i)
    y_scale = std::max(y_scale, std::abs(d.y[i]));
  data.y_scales.push_back(y_scale);
  fit_data(data, options, rec.csv_path, fit);
  centre_unidentified_offset(data, fit, options.max_substep);
  fit.simulated = simulate_for_report(d, fit.setup, param_values(fit), options.max_substep);
  fit.train = compute_metrics(d.y, fit.simulated, range);
  fit.residual_sigma = rms_residual(d.y, fit.simulated, range);
  return fit;
}

GreyboxFit fit_greybox_family(const std::vector<Recording>& recs, const std::string& model,
                              const GreyboxOptions& options, int decimation) {
  const PhenoKind kind = parse_model(model);
  if (recs.empty()) throw InputError("grey-box family fit: no recordings given");
  if (decimation < 1)
    throw InputError("decimation must be at least 1, got " + std::to_string(decimation));
  FLAGS_minloglevel = 3;
  GreyboxFit fit;
  fit.model = pheno_name(kind);
  fit.setup = greybox_setup_for(recs.front(), kind);
  FitData data;
  for (const Recording& rec : recs) {
    const GreyboxSetup setup = greybox_setup_for(rec, kind);
    if (setup.motion_column != fit.setup.motion_column ||
        setup.position_column != fit.setup.position_column ||
        setup.field_column != fit.setup.field_column ||
        setup.output_column != fit.setup.output_column)
      throw InputError(rec.csv_path + ": drive/output columns differ from " +
                       recs.front().csv_path + "; a family fit needs recordings of the same kind");
    DriveSeries d = drive_series(rec, fit.setup, static_cast<std::size_t>(decimation));
    const std::size_t n = d.t.size();
    if (n < 4 * pheno_params(kind).size())
      throw InputError(rec.csv_path + ": too few samples for model " + fit.model + " (" +
                       std::to_string(n) + " after decimation " + std::to_string(decimation) + ")");
    // Every recording weighs the same: its residuals are scaled by its own spread, so the cost is
    // the sum over recordings of (1 - FIT)^2 / 2.
    double mean = std::accumulate(d.y.begin(), d.y.end(), 0.0) / static_cast<double>(n);
    double ss = 0.0;
    for (double y : d.y) ss += (y - mean) * (y - mean);
    if (!(ss > 0.0)) throw InputError(rec.csv_path + ": the output is constant");
    data.ranges.push_back(SampleRange{0, n});
    data.y_scales.push_back(std::sqrt(ss));
    data.series.push_back(std::move(d));
  }
  fit_data(data, options, recs.front().csv_path, fit);
  centre_unidentified_offset(data, fit, options.max_substep);
  fit.train_range = SampleRange{0, 0};
  return fit;
}

std::vector<double> simulate_pheno(const Recording& rec, const GreyboxSetup& setup,
                                   const std::vector<double>& params) {
  const std::vector<PhenoParam>& specs = pheno_params(setup.kind);
  std::vector<double> full = params;  // trailing optional parameters left out are 0
  while (full.size() < specs.size() && specs[full.size()].optional) full.push_back(0.0);
  if (full.size() != specs.size())
    throw InputError("model " + pheno_name(setup.kind) + " takes " + std::to_string(specs.size()) +
                     " parameters, got " + std::to_string(params.size()));
  return simulate_for_report(drive_series(rec, setup), setup, full, GreyboxOptions{}.max_substep);
}

std::vector<double> simulate_greybox(const Recording& rec, const GreyboxFit& fit) {
  GreyboxSetup setup = greybox_setup_for(rec, fit.setup.kind);
  if (setup.field_column.empty() != fit.setup.field_column.empty() ||
      setup.motion_column != fit.setup.motion_column ||
      setup.output_column != fit.setup.output_column)
    throw InputError(rec.csv_path + ": drive/output columns differ from the recording the " +
                     fit.model + " model was fitted on");
  setup.orientation = fit.setup.orientation;
  setup.settings = fit.setup.settings;
  return simulate_pheno(rec, setup, param_values(fit));
}

}  // namespace rheomag::lumped
