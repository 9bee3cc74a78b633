// The valve-chain grey-box model: chain table + field lag + chamber compliance, fitted by Ceres
// (bounded Levenberg-Marquardt on the free-run RK4 simulation, Jets through the states).

#include "identify/valve_chain_fit.hpp"

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "core/error.hpp"
#include "coupling/valve_chain_tabulation.hpp"
#include "identify/multistart_fit.hpp"
#include "identify/standard_errors.hpp"
#include "lumped/ode.hpp"
#include "lumped/pheno_simulation.hpp"

namespace rheomag::identify {

namespace {

constexpr int kParams = 4;  // yield_scale, viscous_scale, field_time_constant, capacitance
enum { kYieldScale, kViscousScale, kTimeConstant, kCapacitance };

/// Drive and output samples as the model sees them: inflow [m^3/s], current [A], output.
struct ChainSeries {
  std::vector<double> t, inflow, current, y;
};

ChainSeries chain_series(const lumped::Recording& rec, const ValveChainSetup& s) {
  ChainSeries d;
  d.t = rec.t;
  d.inflow = rec.column(s.motion_column);
  if (s.motion_column == "velocity")
    for (double& q : d.inflow) q *= s.piston_area;
  d.current = rec.column(s.field_column);
  d.y = rec.column(s.output_column);
  return d;
}

/// Output of the model (pressure or force) for pressure drop dp.
template <class T>
T output_of(const ValveChainSetup& s, const T& dp) {
  return s.output_column == "force" ? s.piston_area * dp + s.gas_force : dp;
}

/// State derivatives: x = (field current [, dp]).
template <class T>
void chain_derivatives(const ValveChainSetup& s, const T* p, double inflow, double current,
                       const T* x, T* dxdt) {
  dxdt[0] = (current - x[0]) / p[kTimeConstant];
  if (s.compliant) {
    const T q =
        lumped::chain_flow(*s.map, x[1], x[0], p[kYieldScale], p[kViscousScale], s.eps_flow);
    dxdt[1] = (inflow - q) / p[kCapacitance];
  }
}

/// Model output for state x at inflow q.
template <class T>
T chain_output(const ValveChainSetup& s, const T* p, double inflow, const T* x) {
  if (s.compliant) return output_of(s, x[1]);
  return output_of(s, lumped::chain_pressure_drop(*s.map, T(inflow), x[0], p[kYieldScale],
                                                  p[kViscousScale], s.eps_flow));
}

template <class T>
void chain_initial_state(const ValveChainSetup& s, const T* p, double inflow, double current,
                         T* x) {
  x[0] = T(current);
  if (s.compliant)
    x[1] = lumped::chain_pressure_drop(*s.map, T(inflow), T(current), p[kYieldScale],
                                       p[kViscousScale], s.eps_flow);
}

/// Free-run RK4 over samples [begin, end); substeps short enough for the lag and the compliance
/// (h |lambda| <= 2 with lambda <= 1/tau and 1/(C s_v R)). False if it diverges or is hopeless.
template <class T>
bool simulate_chain_rk4(const ValveChainSetup& s, const T* p, const ChainSeries& d,
                        std::size_t begin, std::size_t end, double max_substep, T* out) {
  const std::size_t n = s.compliant ? 2 : 1;
  std::array<T, 2> x, k1, k2, k3, k4, tmp;
  chain_initial_state(s, p, d.inflow[begin], d.current[begin], x.data());
  out[0] = chain_output(s, p, d.inflow[begin], x.data());
  double rate = 1.0 / lumped::value_of(p[kTimeConstant]);
  if (s.compliant)
    rate = std::max(rate, 1.0 / (lumped::value_of(p[kCapacitance]) *
                                 lumped::value_of(p[kViscousScale]) * s.map->viscous_resistance));
  if (!std::isfinite(rate)) return false;
  for (std::size_t i = begin; i + 1 < end; ++i) {
    const double dt = d.t[i + 1] - d.t[i];
    if (rate * dt > 2e4) return false;
    const int substeps = std::max({1, static_cast<int>(std::ceil(dt / max_substep)),
                                   static_cast<int>(std::ceil(dt * rate / 2.0))});
    const double h = dt / substeps;
    auto q_at = [&](double w) { return d.inflow[i] + w * (d.inflow[i + 1] - d.inflow[i]); };
    auto i_at = [&](double w) { return d.current[i] + w * (d.current[i + 1] - d.current[i]); };
    for (int j = 0; j < substeps; ++j) {
      const double w0 = static_cast<double>(j) / substeps, wm = (j + 0.5) / substeps,
                   w1 = static_cast<double>(j + 1) / substeps;
      chain_derivatives(s, p, q_at(w0), i_at(w0), x.data(), k1.data());
      for (std::size_t k = 0; k < n; ++k) tmp[k] = x[k] + 0.5 * h * k1[k];
      chain_derivatives(s, p, q_at(wm), i_at(wm), tmp.data(), k2.data());
      for (std::size_t k = 0; k < n; ++k) tmp[k] = x[k] + 0.5 * h * k2[k];
      chain_derivatives(s, p, q_at(wm), i_at(wm), tmp.data(), k3.data());
      for (std::size_t k = 0; k < n; ++k) tmp[k] = x[k] + h * k3[k];
      chain_derivatives(s, p, q_at(w1), i_at(w1), tmp.data(), k4.data());
      for (std::size_t k = 0; k < n; ++k)
        x[k] += h / 6.0 * (k1[k] + 2.0 * k2[k] + 2.0 * k3[k] + k4[k]);
    }
    out[i + 1 - begin] = chain_output(s, p, d.inflow[i + 1], x.data());
    if (!std::isfinite(lumped::value_of(out[i + 1 - begin]))) return false;
  }
  return true;
}

/// Normalised parameters theta -> physical: scales as they are, tau and C log-scaled.
struct Normalisation {
  double tau0 = 0.02, c0 = 1e-12;
  template <class T>
  std::array<T, kParams> physical(const T* theta) const {
    using std::exp;
    return {theta[0], theta[1], tau0 * exp(theta[2]), c0 * exp(theta[3])};
  }
};

/// Residuals (model - measured) / y_scale on the training samples.
struct ChainResidual {
  const ChainSeries* d;
  const ValveChainSetup* setup;
  Normalisation norm;
  lumped::SampleRange range;
  double y_scale;
  double max_substep;
  template <class T>
  bool operator()(const T* theta, T* residual) const {
    const std::array<T, kParams> p = norm.physical(theta);
    std::vector<T> yhat(range.size());
    if (!simulate_chain_rk4(*setup, p.data(), *d, range.begin, range.end, max_substep, yhat.data()))
      return false;
    for (std::size_t i = 0; i < range.size(); ++i)
      residual[i] = (yhat[i] - d->y[range.begin + i]) / y_scale;
    return true;
  }
};

/// The model as an OdeSystem for the stiff integrator (reported simulations).
class ChainOde : public lumped::OdeSystem {
 public:
  ChainOde(const ValveChainSetup& s, const std::vector<double>& p, const ChainSeries& d)
      : s_(s), p_(p), d_(d) {}
  std::size_t state_size() const override { return s_.compliant ? 2 : 1; }
  void derivatives(double t, const double* x, double* dxdt) const override {
    auto it = std::upper_bound(d_.t.begin(), d_.t.end(), t);
    std::size_t i = it == d_.t.begin() ? 0 : static_cast<std::size_t>(it - d_.t.begin()) - 1;
    i = std::min(i, d_.t.size() - 2);
    const double w = std::clamp((t - d_.t[i]) / (d_.t[i + 1] - d_.t[i]), 0.0, 1.0);
    chain_derivatives(s_, p_.data(), d_.inflow[i] + w * (d_.inflow[i + 1] - d_.inflow[i]),
                      d_.current[i] + w * (d_.current[i + 1] - d_.current[i]), x, dxdt);
  }
  std::vector<double> state_scales() const override {
    double dp = 1.0;
    for (double v : d_.y) dp = std::max(dp, std::abs(v));
    if (s_.output_column == "force") dp /= s_.piston_area;
    return s_.compliant ? std::vector<double>{1.0, dp} : std::vector<double>{1.0};
  }

 private:
  const ValveChainSetup& s_;
  const std::vector<double>& p_;
  const ChainSeries& d_;
};

std::vector<double> simulate_series(const ChainSeries& d, const ValveChainSetup& s,
                                    const std::vector<double>& p) {
  ChainOde ode(s, p, d);
  std::vector<double> x0(ode.state_size());
  chain_initial_state(s, p.data(), d.inflow[0], d.current[0], x0.data());
  lumped::IntegratorOptions opt;
  opt.abs_tol = 1e-8;
  opt.rel_tol = 1e-7;
  const auto states = lumped::integrate_stiff(ode, x0, d.t, opt);
  std::vector<double> y(d.t.size());
  for (std::size_t i = 0; i < y.size(); ++i)
    y[i] = chain_output(s, p.data(), d.inflow[i], states[i].data());
  return y;
}

}  // namespace

ValveChainSetup valve_chain_setup_for(const lumped::Recording& rec,
                                      const ValveChainFitOptions& options) {
  const std::string where = rec.meta.sidecar_path.empty() ? rec.csv_path : rec.meta.sidecar_path;
  if (rec.meta.valve.case_file.empty())
    throw InputError(where +
                     ": [valve] has no 'case' (an FE case file); model valve-chain takes its "
                     "static map from the fluid chain of that case");
  ValveChainSetup s;
  const auto& drive = rec.meta.drive;
  auto driven = [&](const std::string& c) {
    return std::find(drive.begin(), drive.end(), c) != drive.end() && rec.columns.count(c);
  };
  if (driven("velocity"))
    s.motion_column = "velocity";
  else if (driven("flow"))
    s.motion_column = "flow";
  else
    throw InputError(where + ": [recording] drive has neither 'velocity' nor 'flow'; model " +
                     "valve-chain is driven by the flow through the valve");
  if (driven("current"))
    s.field_column = "current";
  else if (driven("current_cmd"))
    s.field_column = "current_cmd";
  else
    throw InputError(where + ": [recording] drive has no 'current' or 'current_cmd'; model " +
                     "valve-chain needs the coil current");
  s.output_column = rec.meta.output;
  if (s.output_column != "pressure" && s.output_column != "force")
    throw InputError(where + ": [recording] output '" + s.output_column +
                     "': model valve-chain explains 'pressure' or 'force'");
  s.compliant = s.motion_column == "velocity";
  if (s.compliant || s.output_column == "force") {
    if (!rec.meta.rig.piston_area)
      throw InputError(where + ": [rig] piston_area is needed (m^2) to turn the velocity into " +
                       "flow / the pressure into force");
    s.piston_area = *rec.meta.rig.piston_area;
  }
  s.gas_force = rec.meta.rig.gas_force.value_or(0.0);
  double i_max = 0.0, q_max = 0.0, q_rms = 0.0;
  for (double i : rec.column(s.field_column)) i_max = std::max(i_max, std::abs(i));
  const auto& motion = rec.column(s.motion_column);
  const double area = s.motion_column == "velocity" ? s.piston_area : 1.0;
  for (double m : motion) {
    q_max = std::max(q_max, std::abs(m * area));
    q_rms += m * area * m * area;
  }
  q_rms = std::sqrt(q_rms / static_cast<double>(motion.size()));
  if (!(q_max > 0.0)) throw InputError(rec.csv_path + ": the flow drive is zero throughout");
  s.eps_flow = 1e-3 * q_rms;
  s.map = coupling::tabulate_valve_chain(rec.meta.valve.case_file, i_max > 0.0 ? i_max : 1.0, q_max,
                                         options.current_points, options.flow_points);
  return s;
}

ValveChainFit fit_valve_chain(const lumped::Recording& rec, const ValveChainFitOptions& options) {
  FLAGS_minloglevel = 3;  // Ceres logs failed trial steps through glog; results are reported here
  ValveChainFit fit;
  fit.setup = valve_chain_setup_for(rec, options);
  const ValveChainSetup& s = fit.setup;
  const ChainSeries d = chain_series(rec, s);
  const lumped::SampleRange range = options.train.value_or(lumped::SampleRange{0, d.t.size()});
  if (range.end > d.t.size() || range.begin >= range.end)
    throw InputError(rec.csv_path + ": training range is outside the " +
                     std::to_string(d.t.size()) + " samples");
  if (range.size() < 4 * kParams)
    throw InputError(rec.csv_path + ": model valve-chain needs at least " +
                     std::to_string(4 * kParams) + " training samples, got " +
                     std::to_string(range.size()));
  fit.train_range = range;
  double y_scale = 0.0;
  for (std::size_t i = range.begin; i < range.end; ++i)
    y_scale = std::max(y_scale, std::abs(d.y[i]));
  if (!(y_scale > 0.0))
    throw InputError(rec.csv_path + ": the output is zero on the training samples");

  // Nominal compliance: the pressure builds up over ~0.1 s at the rms flow.
  Normalisation norm;
  const double dp_scale = s.output_column == "force" ? y_scale / s.piston_area : y_scale;
  norm.c0 = lumped::rms_on(d.inflow, range) * 0.1 / dp_scale;
  // Smallest compliance: the pressure settles within a tenth of a sample at the nominal
  // resistance, indistinguishable from an incompressible rig at this sampling rate (and it keeps
  // the RK4 substeps few).
  const double dt_median = (d.t[range.end - 1] - d.t[range.begin]) /
                           static_cast<double>(std::max<std::size_t>(1, range.size() - 1));
  const double c_min = 0.1 * dt_median / s.map->viscous_resistance;
  const std::array<double, kParams> lower = {1e-2, 1e-2, std::log(1e-4 / norm.tau0),
                                             std::min(std::log(c_min / norm.c0), -1.0)};
  const std::array<double, kParams> upper = {1e2, 1e3, std::log(10.0 / norm.tau0), std::log(1e4)};
  ChainResidual functor{&d, &s, norm, range, y_scale, options.max_substep};

  std::mt19937 rng(options.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  BestStart<kParams> best;
  for (int start = 0; start < std::max(1, options.starts); ++start) {
    std::array<double, kParams> theta = {1.0, 1.0, 0.0, 0.0};
    if (start > 0) {
      theta[0] *= std::exp(0.5 * normal(rng));
      theta[1] *= std::exp(0.5 * normal(rng));
      theta[2] += 1.5 * normal(rng);
      theta[3] += 1.5 * normal(rng);
      for (int k = 0; k < kParams; ++k) theta[k] = std::clamp(theta[k], lower[k], upper[k]);
    }
    ceres::Problem problem;
    problem.AddResidualBlock(
        new CachedCostFunction(
            new ceres::AutoDiffCostFunction<ChainResidual, ceres::DYNAMIC, kParams>(
                new ChainResidual(functor), static_cast<int>(range.size()))),
        nullptr, theta.data());
    for (int k = 0; k < kParams; ++k) {
      problem.SetParameterLowerBound(theta.data(), k, lower[k]);
      problem.SetParameterUpperBound(theta.data(), k, upper[k]);
    }
    if (!s.compliant) problem.SetManifold(theta.data(), new ceres::SubsetManifold(kParams, {3}));
    const ceres::Solver::Options so = greybox_solver_options(options.max_iterations, 20);
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    ++fit.starts_run;
    best.offer(summary, theta, start);
  }
  if (!best.found())
    throw ConvergenceError("valve-chain fit: no starting point gave a finite simulation");

  // Standard errors on the normalised parameters, mapped to physical ones (delta method).
  const int m = static_cast<int>(range.size());
  Eigen::Matrix<double, Eigen::Dynamic, kParams, Eigen::RowMajor> jac;
  Eigen::VectorXd res;
  residual_jacobian(functor, m, best.theta.data(), jac, res);
  fit.best_start = best.start;
  fit.converged = best.converged;
  const int nf = s.compliant ? kParams : kParams - 1;
  const std::vector<std::optional<double>> se =
      jacobian_standard_errors(Eigen::MatrixXd(jac.leftCols(nf)), res);
  const std::array<double, kParams> value = norm.physical(best.theta.data());
  fit.params = valve_chain_parameters(value, s.compliant);
  for (int k = 0; k < nf; ++k) {
    FittedParameter& fp = fit.params[k];
    fp.at_bound = std::abs(best.theta[k] - lower[k]) < 1e-6 * (upper[k] - lower[k]) ||
                  std::abs(best.theta[k] - upper[k]) < 1e-6 * (upper[k] - lower[k]);
    // d(physical)/d(theta) = 1 for the scales, = value for the log-scaled tau and C.
    if (se[k]) fp.standard_error = *se[k] * (k < 2 ? 1.0 : value[k]);
  }
  std::vector<double> p(value.begin(), value.end());
  fit.simulated = simulate_series(d, s, p);
  fit.train = lumped::compute_metrics(d.y, fit.simulated, range);
  fit.residual_sigma = rms_residual(d.y, fit.simulated, range);
  return fit;
}

std::vector<FittedParameter> valve_chain_parameters(const std::array<double, kParams>& values,
                                                    bool compliant) {
  static const std::array<const char*, kParams> names = {
      "yield_scale", "viscous_scale", "field_time_constant", "hydraulic_capacitance"};
  static const std::array<const char*, kParams> units = {"1", "1", "s", "m^3/Pa"};
  const int nf = compliant ? kParams : kParams - 1;
  std::vector<FittedParameter> params;
  for (int k = 0; k < kParams; ++k) {
    FittedParameter fp;
    fp.name = names[k];
    fp.unit = units[k];
    fp.fixed = k >= nf;
    fp.value = fp.fixed ? 0.0 : values[k];
    params.push_back(fp);
  }
  return params;
}

std::vector<double> simulate_valve_chain(const lumped::Recording& rec, const ValveChainSetup& setup,
                                         const std::vector<double>& params) {
  if (params.size() != kParams)
    throw InputError("model valve-chain takes 4 parameters, got " + std::to_string(params.size()));
  return simulate_series(chain_series(rec, setup), setup, params);
}

std::vector<double> simulate_valve_chain(const lumped::Recording& rec, const ValveChainFit& fit) {
  ValveChainSetup setup = fit.setup;  // same valve table and settings, this recording's columns
  const ValveChainSetup other = [&] {
    ValveChainSetup o = setup;
    const auto& drive = rec.meta.drive;
    auto driven = [&](const std::string& c) {
      return std::find(drive.begin(), drive.end(), c) != drive.end() && rec.columns.count(c);
    };
    if (!driven(setup.motion_column) || !driven(setup.field_column) ||
        rec.meta.output != setup.output_column)
      throw InputError(rec.csv_path + ": drive/output columns differ from the recording the " +
                       "valve-chain model was fitted on");
    if (rec.meta.rig.piston_area) o.piston_area = *rec.meta.rig.piston_area;
    return o;
  }();
  std::vector<double> values;
  for (const auto& p : fit.params) values.push_back(p.value);
  return simulate_valve_chain(rec, other, values);
}

}  // namespace rheomag::identify
