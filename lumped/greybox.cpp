// Grey-box fits: Ceres Levenberg-Marquardt with bounds on normalised parameters, residuals from a
// fixed-step RK4 free-run simulation differentiated by Jets; reported output from rosenbrock4.

#include "lumped/greybox.hpp"

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>

#include "core/error.hpp"
#include "lumped/multistart_fit.hpp"
#include "lumped/ode.hpp"
#include "lumped/standard_errors.hpp"

namespace rheomag::lumped {

namespace {

/// Drive and output samples of one recording as a model sees them.
struct DriveSeries {
  std::vector<double> t, position, motion, field, y;
  PhenoDrive at(std::size_t i) const { return {position[i], motion[i], field[i]}; }
  /// Linear interpolation between sample i and i+1 at fraction w in [0, 1].
  PhenoDrive between(std::size_t i, double w) const {
    return {position[i] + w * (position[i + 1] - position[i]),
            motion[i] + w * (motion[i + 1] - motion[i]), field[i] + w * (field[i + 1] - field[i])};
  }
};

DriveSeries drive_series(const Recording& rec, const GreyboxSetup& setup) {
  DriveSeries d;
  d.t = rec.t;
  d.motion = rec.column(setup.motion_column);
  d.y = rec.column(setup.output_column);
  d.field = setup.field_column.empty() ? std::vector<double>(d.t.size(), 0.0)
                                       : rec.column(setup.field_column);
  if (!setup.position_column.empty()) {
    d.position = rec.column(setup.position_column);
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

/// Free-run RK4 simulation of samples [begin, end) with substeps no longer than max_substep and
/// short enough for the stiffest rate. Returns false if the state became non-finite.
template <class T>
bool simulate_rk4(PhenoKind kind, const T* p, const DriveSeries& d, const PhenoSettings& s,
                  std::size_t begin, std::size_t end, double max_substep, T* out) {
  constexpr std::size_t kMaxStates = 3;
  const std::size_t n = pheno_state_count(kind);
  std::array<T, kMaxStates> x, k1, k2, k3, k4, tmp;
  pheno_initial_state(kind, p, d.at(begin), s, x.data());
  out[0] = pheno_output(kind, p, d.at(begin), s, x.data());
  double rate_previous = 0.0;
  for (std::size_t i = begin; i + 1 < end; ++i) {
    const double dt = d.t[i + 1] - d.t[i];
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

/// Residuals (model - orientation * measured) / y_scale on a sample range, in normalised params.
template <int N>
struct FitResidual {
  const DriveSeries* d;
  PhenoKind kind;
  PhenoSettings settings;
  SampleRange range;
  std::array<double, N> scale;
  double orientation;
  double y_scale;
  double max_substep;

  template <class T>
  bool operator()(const T* theta, T* residual) const {
    std::array<T, N> p;
    for (int k = 0; k < N; ++k) p[k] = theta[k] * scale[k];
    std::vector<T> yhat(range.size());
    if (!simulate_rk4(kind, p.data(), *d, settings, range.begin, range.end, max_substep,
                      yhat.data()))
      return false;
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

ParamGuess initial_guess(PhenoKind kind, const DriveSeries& d, SampleRange r, double orientation,
                         bool has_field) {
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
  try {
    return simulate_stiff(d, setup, params);
  } catch (const ConvergenceError&) {
    std::vector<double> y(d.t.size());
    if (!simulate_rk4(setup.kind, params.data(), d, setup.settings, 0, d.t.size(), max_substep,
                      y.data()))
      throw ConvergenceError("model " + pheno_name(setup.kind) +
                             ": the simulation diverges with these parameters");
    for (double& v : y) v *= setup.orientation;
    return y;
  }
}

/// One multi-start fit of a model with N parameters; fills `fit`.
template <int N>
void run_fit(const DriveSeries& d, const GreyboxSetup& setup, const ParamGuess& guess,
             SampleRange range, const GreyboxOptions& options, GreyboxFit& fit) {
  double y_scale = 0.0;
  for (std::size_t i = range.begin; i < range.end; ++i)
    y_scale = std::max(y_scale, std::abs(d.y[i]));
  if (!(y_scale > 0.0))
    throw InputError("grey-box fit: the output is zero on the training samples");
  FitResidual<N> functor{&d, setup.kind,        setup.settings, range,
                         {}, setup.orientation, y_scale,        options.max_substep};
  for (int k = 0; k < N; ++k) functor.scale[k] = guess.scale[k];
  std::vector<int> fixed;
  for (int k = 0; k < N; ++k)
    if (guess.fixed[k]) fixed.push_back(k);

  // Starting points are drawn first, in order, so the result does not depend on which thread
  // finishes first; the starts are independent Ceres problems, solved `threads` at a time.
  std::mt19937 rng(options.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  const int starts = std::max(1, options.starts);
  std::vector<std::array<double, N>> thetas(static_cast<std::size_t>(starts));
  for (int start = 0; start < starts; ++start) {
    for (int k = 0; k < N; ++k) {
      double value = guess.nominal[k];
      if (start > 0 && !guess.fixed[k]) {
        value =
            value != 0.0 ? value * std::exp(0.7 * normal(rng)) : 0.3 * guess.scale[k] * normal(rng);
        const double margin = 1e-6 * (guess.upper[k] - guess.lower[k]);
        value = std::clamp(value, guess.lower[k] + margin, guess.upper[k] - margin);
      }
      thetas[static_cast<std::size_t>(start)][k] = value / guess.scale[k];
    }
  }
  std::vector<ceres::Solver::Summary> summaries(static_cast<std::size_t>(starts));
  const auto solve_start = [&](std::size_t start) {
    std::array<double, N>& theta = thetas[start];
    ceres::Problem problem;
    auto* cost = new ceres::AutoDiffCostFunction<FitResidual<N>, ceres::DYNAMIC, N>(
        new FitResidual<N>(functor), static_cast<int>(range.size()));
    problem.AddResidualBlock(cost, nullptr, theta.data());
    for (int k = 0; k < N; ++k) {
      if (guess.fixed[k]) continue;
      problem.SetParameterLowerBound(theta.data(), k, guess.lower[k] / guess.scale[k]);
      problem.SetParameterUpperBound(theta.data(), k, guess.upper[k] / guess.scale[k]);
    }
    if (!fixed.empty()) problem.SetManifold(theta.data(), new ceres::SubsetManifold(N, fixed));
    const ceres::Solver::Options so =
        greybox_solver_options(options.max_iterations, 50);  // trial steps into unstable regions
    ceres::Solve(so, &problem, &summaries[start]);
  };
  for_each_start(static_cast<std::size_t>(starts), fit_threads(options.threads), solve_start);
  BestStart<N> best;
  for (int start = 0; start < starts; ++start) {
    ++fit.starts_run;
    best.offer(summaries[static_cast<std::size_t>(start)], thetas[static_cast<std::size_t>(start)],
               start);
  }
  if (!best.found())
    throw ConvergenceError("grey-box fit of " + fit.model +
                           ": no starting point gave a finite simulation");

  // Standard errors: cov = (J^T J)^-1 sigma^2 on the free parameters (normalised), then scaled.
  const int m = static_cast<int>(range.size());
  Eigen::Matrix<double, Eigen::Dynamic, N, Eigen::RowMajor> jac;
  Eigen::VectorXd res;
  residual_jacobian(functor, m, best.theta.data(), jac, res);
  fit.best_start = best.start;
  fit.converged = best.converged;
  std::vector<int> free;
  for (int k = 0; k < N; ++k)
    if (!guess.fixed[k]) free.push_back(k);
  const int nf = static_cast<int>(free.size());
  Eigen::MatrixXd jf(m, nf);
  for (int c = 0; c < nf; ++c) jf.col(c) = jac.col(free[c]);
  const std::vector<std::optional<double>> se = jacobian_standard_errors(jf, res);

  const auto& specs = pheno_params(setup.kind);
  fit.params.clear();
  for (int k = 0; k < N; ++k) {
    FittedParameter fp;
    fp.name = specs[k].name;
    fp.unit = unit_string(specs[k].unit, setup);
    fp.value = best.theta[k] * guess.scale[k];
    fp.fixed = guess.fixed[k];
    if (!fp.fixed) {
      const double span = guess.upper[k] - guess.lower[k];
      fp.at_bound = std::abs(fp.value - guess.lower[k]) < 1e-6 * span ||
                    std::abs(fp.value - guess.upper[k]) < 1e-6 * span;
      const int c = static_cast<int>(std::find(free.begin(), free.end(), k) - free.begin());
      if (se[c]) fp.standard_error = *se[c] * guess.scale[k];
    }
    fit.params.push_back(fp);
  }
}

}  // namespace

const std::vector<std::string>& greybox_model_names() {
  static const std::vector<std::string> names = {"bingham", "lugre", "bouc-wen", "maxwell", "dahl"};
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
  PhenoKind kind;
  if (!parse_pheno_kind(model, kind))
    throw InputError("unknown grey-box model '" + model +
                     "' (expected bingham, lugre, bouc-wen, maxwell or dahl)");
  FLAGS_minloglevel = 3;  // Ceres logs failed trial steps through glog; results are reported here
  GreyboxFit fit;
  fit.model = pheno_name(kind);
  fit.setup = greybox_setup_for(rec, kind);
  const DriveSeries d = drive_series(rec, fit.setup);
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
  // Orientation: make the output grow with the motion (mrdamper's force has the opposite sign).
  double corr = 0.0;
  for (std::size_t i = range.begin; i < range.end; ++i) corr += d.y[i] * d.motion[i];
  fit.setup.orientation = corr < 0.0 ? -1.0 : 1.0;
  const double m_rms = rms(d.motion, range);
  if (!(m_rms > 0.0)) throw InputError(rec.csv_path + ": the motion drive is zero throughout");
  fit.setup.settings.eps = options.eps_fraction * m_rms;
  fit.setup.settings.motion_scale = m_rms;
  const ParamGuess guess =
      initial_guess(kind, d, range, fit.setup.orientation, !fit.setup.field_column.empty());
  switch (kind) {
    case PhenoKind::bingham:
      run_fit<6>(d, fit.setup, guess, range, options, fit);
      break;
    case PhenoKind::lugre:
      run_fit<8>(d, fit.setup, guess, range, options, fit);
      break;
    case PhenoKind::bouc_wen:
      run_fit<13>(d, fit.setup, guess, range, options, fit);
      break;
    case PhenoKind::maxwell:
      run_fit<6>(d, fit.setup, guess, range, options, fit);
      break;
    case PhenoKind::dahl:
      run_fit<6>(d, fit.setup, guess, range, options, fit);
      break;
  }
  std::vector<double> values;
  for (const auto& p : fit.params) values.push_back(p.value);
  fit.simulated = simulate_for_report(d, fit.setup, values, options.max_substep);
  fit.train = compute_metrics(d.y, fit.simulated, range);
  fit.residual_sigma = rms_residual(d.y, fit.simulated, range);
  return fit;
}

std::vector<double> simulate_pheno(const Recording& rec, const GreyboxSetup& setup,
                                   const std::vector<double>& params) {
  if (params.size() != pheno_params(setup.kind).size())
    throw InputError("model " + pheno_name(setup.kind) + " takes " +
                     std::to_string(pheno_params(setup.kind).size()) + " parameters, got " +
                     std::to_string(params.size()));
  return simulate_for_report(drive_series(rec, setup), setup, params, GreyboxOptions{}.max_substep);
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
  std::vector<double> values;
  for (const auto& p : fit.params) values.push_back(p.value);
  return simulate_pheno(rec, setup, values);
}

}  // namespace rheomag::lumped
