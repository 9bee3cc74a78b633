// Free run of a phenomenological model on a recording: its drive series, the stiff integrator
// and the fixed-step RK4 fallback.

#include "lumped/pheno_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.hpp"
#include "lumped/leading_rest.hpp"
#include "lumped/motion_glitches.hpp"
#include "lumped/ode.hpp"
#include "lumped/output_smoothing.hpp"
#include "lumped/pheno_free_run.hpp"

namespace rheomag::lumped {

namespace {

/// Every `step`-th sample of `v`.
std::vector<double> every(const std::vector<double>& v, std::size_t step) {
  std::vector<double> out;
  for (std::size_t i = 0; i < v.size(); i += step) out.push_back(v[i]);
  return out;
}

/// `v` read `lead` later on its time base `t`: v(t_i + lead), linear between samples, the first
/// and last values held beyond the ends.
std::vector<double> read_later(const std::vector<double>& t, const std::vector<double>& v,
                               double lead) {
  if (lead == 0.0 || v.size() < 2) return v;
  std::vector<double> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double at = t[i] + lead;
    const auto it = std::upper_bound(t.begin(), t.end(), at);
    if (it == t.begin()) {
      out[i] = v.front();
    } else if (it == t.end()) {
      out[i] = v.back();
    } else {
      const auto k = static_cast<std::size_t>(it - t.begin()) - 1;
      out[i] = v[k] + (at - t[k]) / (t[k + 1] - t[k]) * (v[k + 1] - v[k]);
    }
  }
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
    const double X = std::max(rms_on(d_.position, all), 1e-12);
    switch (setup_.kind) {
      case PhenoKind::bouc_wen:
        return {X, X, std::max(1.0, rms_on(d_.field, all))};
      case PhenoKind::maxwell:
        return {std::max(rms_on(d_.y, all), 1.0)};  // [N or Pa]
      case PhenoKind::damper:
        return {std::max(rms_on(d_.y, all), 1.0), 1.0, std::max(1.0, rms_on(d_.field, all))};
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

/// The rest before `motion` (the recording's motion as the model reads it) to tare the output to.
std::size_t rest_before(const Recording& rec, const GreyboxSetup& setup,
                        const std::vector<double>& motion) {
  const std::vector<double>& y = rec.column(setup.output_column);
  const auto [lo, hi] = std::minmax_element(y.begin(), y.end());
  // A constant output column is a placeholder, not a measurement to tare to.
  if (y.empty() || !(*hi > *lo) || output_mean_removed(y)) return 0;
  return leading_rest(rec.t, motion);
}

}  // namespace

std::size_t tared_rest(const Recording& rec, const GreyboxSetup& setup) {
  return rest_before(rec, setup, column_without_glitches(rec, setup.motion_column));
}

DriveSeries drive_series(const Recording& rec, const GreyboxSetup& setup, std::size_t step) {
  DriveSeries d;
  d.t = every(rec.t, step);
  // A motion's single-sample acquisition glitches are not motion: an inertia would read each as
  // an acceleration spike (motion_glitches.hpp).
  const std::vector<double> motion = column_without_glitches(rec, setup.motion_column);
  d.motion = every(read_later(rec.t, motion, setup.motion_lead), step);
  d.y = every(rec.column(setup.output_column), step);
  d.field = setup.field_column.empty() ? std::vector<double>(d.t.size(), 0.0)
                                       : every(rec.column(setup.field_column), step);
  d.acceleration = rate_of(d.t, d.motion);
  d.period = drive_period(d.t, d.motion);
  d.mean_removed = output_mean_removed(rec.column(setup.output_column));
  // The rest of the full recording, in kept samples (0, step, 2 step, ... below it).
  const std::size_t rest = rest_before(rec, setup, motion);
  d.rest_samples = step > 0 ? (rest + step - 1) / step : 0;
  if (d.rest_samples >= d.t.size()) d.rest_samples = 0;
  for (std::size_t i = 0; i < d.rest_samples; ++i) d.rest_level += d.y[i];
  if (d.rest_samples > 0) d.rest_level /= static_cast<double>(d.rest_samples);
  if (!setup.position_column.empty()) {
    d.position = every(column_without_glitches(rec, setup.position_column), step);
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

double rms_on(const std::vector<double>& v, SampleRange r) {
  double s = 0.0;
  for (std::size_t i = r.begin; i < r.end; ++i) s += v[i] * v[i];
  return std::sqrt(s / static_cast<double>(r.size()));
}

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
  process_output(setup.kind, params.data(), d, setup.settings, setup.orientation, true,
                 SampleRange{0, d.t.size()}, y.data());
  return y;
}

std::vector<double> simulate_pheno(const Recording& rec, const GreyboxSetup& setup,
                                   const std::vector<double>& params) {
  const std::vector<PhenoParam>& specs = pheno_params(setup.kind);
  std::vector<double> full = params;  // trailing optional parameters left out are 0
  while (full.size() < specs.size() && specs[full.size()].optional) full.push_back(0.0);
  if (full.size() != specs.size())
    throw InputError("model " + pheno_name(setup.kind) + " takes " + std::to_string(specs.size()) +
                     " parameters, got " + std::to_string(params.size()));
  return simulate_for_report(drive_series(rec, setup), setup, full, kPhenoMaxSubstep);
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

}  // namespace rheomag::lumped
