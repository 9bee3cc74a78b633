#pragma once
// The fixed-step free run of a phenomenological model as a template, so that Ceres Jets flow
// through it: RK4 limited by the stiffest rate, or the damper and Bouc-Wen models' exponential
// midpoint steps; then the recording's own processing of the output (smoothing, mean).

#include <algorithm>
#include <array>
#include <cmath>

#include "lumped/output_smoothing.hpp"
#include "lumped/pheno_simulation.hpp"

namespace rheomag::lumped {

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
/// recording, the output's own mean removed; or, if the recording starts at rest and `range` starts
/// with it, the output tared to the recording's level at rest (DriveSeries::rest_samples) plus
/// orientation (offset - PhenoSettings::rest_reference) where that is set. `out` holds the model
/// times `orientation` if `oriented`, else the model itself (compared with orientation x output).
template <class T>
void process_output(PhenoKind kind, const T* p, const DriveSeries& d, const PhenoSettings& s,
                    double orientation, bool oriented, SampleRange range, T* out) {
  if (d.period > 0.0)
    centred_boxcar(&d.t[range.begin], range.size(), T(p[pheno_smoothing_index(kind)] * d.period),
                   out);
  if (d.mean_removed && range.begin == 0 && range.end == d.t.size()) {
    remove_mean(out, range.size());
  } else if (d.rest_samples > 0 && range.begin == 0 && range.end > d.rest_samples) {
    // The level wanted over the rest, in the model's orientation.
    T level = T(orientation * d.rest_level);
    if (const int k = pheno_param_index(kind, "offset"); k >= 0 && std::isfinite(s.rest_reference))
      level += p[k] - s.rest_reference;
    if (oriented) level *= orientation;
    tare(out, range.size(), d.rest_samples, level);
  }
}

/// Models integrated by their own stiff-stable exponential step (damper_step, bouc_wen_step).
inline bool has_exponential_step(PhenoKind kind) {
  return kind == PhenoKind::damper || kind == PhenoKind::bouc_wen;
}

/// One exponential midpoint step of the damper or Bouc-Wen model (damper_step, bouc_wen_step).
/// Flattened, i.e. every Jet operation inside inlined: GCC left the 12-15-lane Jet additions and
/// products out of line, which was half of a fit's time; the arithmetic is the same.
template <class T>
[[gnu::flatten]] void exponential_step(PhenoKind kind, const T* p, const PhenoDrive& start,
                                       const PhenoDrive& middle, const PhenoSettings& s, double h,
                                       FieldFilterGains<T>& gains, T* x) {
  if (kind == PhenoKind::damper)
    damper_step(p, start, middle, s, h, gains, x);
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
  FieldFilterGains<T> gains;  // the field filter's, kept from step to step
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

}  // namespace rheomag::lumped
