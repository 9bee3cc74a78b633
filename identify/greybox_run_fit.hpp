#pragma once
// The multi-start Ceres fit of a grey-box model with N parameters of which NF are free: residuals
// of the fixed-step free run (lumped/pheno_free_run.hpp) differentiated by Jets, bounded
// Levenberg-Marquardt from each start, standard errors from the Jacobian. Included only by the
// files that instantiate it (greybox_fit_*.cpp): every instantiation compiles every model's
// derivatives for its Jet type.

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <random>

#include "core/error.hpp"
#include "identify/greybox_fit_data.hpp"
#include "identify/multistart_fit.hpp"
#include "identify/standard_errors.hpp"
#include "identify/viscosity_nuisance.hpp"
#include "lumped/pheno_free_run.hpp"

namespace rheomag::identify::greybox_detail {

/// Residuals (model - orientation * measured) / y_scale on a sample range, as a function of the NF
/// free ones of the N normalised parameters (the held ones are constants, so the Jets carry only
/// the free derivatives).
template <int N, int NF>
struct FitResidual {
  const lumped::DriveSeries* d;
  lumped::PhenoKind kind;
  lumped::PhenoSettings settings;
  lumped::SampleRange range;
  std::array<double, N> scale;
  std::array<double, N> held;      ///< normalised values of the held parameters
  std::array<int, NF> free_index;  ///< parameter number of each free parameter
  double orientation;
  double y_scale;
  double max_substep;
  double viscous_factor = 1.0;    ///< this series' factor on the viscosity-scaled parameters
  std::array<bool, N> viscous{};  ///< which parameters it scales

  template <class T>
  bool operator()(const T* theta, T* residual) const {
    std::array<T, N> p;
    for (int k = 0; k < N; ++k) p[k] = T(held[k] * scale[k]);
    for (int j = 0; j < NF; ++j) p[free_index[j]] = theta[j] * scale[free_index[j]];
    for (int k = 0; k < N; ++k)
      if (viscous[k]) p[k] *= viscous_factor;
    std::vector<T> yhat(range.size());
    if (!lumped::simulate_rk4(kind, p.data(), *d, settings, range.begin, range.end, max_substep,
                              yhat.data()))
      return false;
    lumped::process_output(kind, p.data(), *d, settings, orientation, false, range, yhat.data());
    for (std::size_t i = 0; i < range.size(); ++i)
      residual[i] = (yhat[i] - orientation * d->y[range.begin + i]) / y_scale;
    return true;
  }
};

/// Reports each Levenberg-Marquardt iteration of a start as progress: the iterations of every
/// start so far out of their bound. The starts run on several threads; `serial` makes the
/// caller's callback run for one of them at a time (it appends to a list, prints a line or
/// calls into Python, none of which may be entered twice at once).
class IterationReport : public ceres::IterationCallback {
 public:
  IterationReport(const ProgressCallback& progress, std::mutex& serial,
                  std::atomic<int>& iterations, std::chrono::steady_clock::time_point start,
                  std::string stage, int bound)
      : progress_(progress),
        serial_(serial),
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
    const std::lock_guard<std::mutex> lock(serial_);
    progress_(e);
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const ProgressCallback& progress_;
  std::mutex& serial_;
  std::atomic<int>& iterations_;
  std::chrono::steady_clock::time_point start_;
  std::string stage_;
  int bound_;
};

template <int N, int NF>
void run_fit(const FitData& data, const lumped::GreyboxSetup& setup, const ParamGuess& guess,
             const GreyboxOptions& options, GreyboxFit& fit) {
  std::array<int, NF> free{};
  for (int k = 0, j = 0; k < N; ++k)
    if (!guess.fixed[k]) free[j++] = k;
  const auto pinned = [&](int j) {
    return !guess.pinned.empty() && guess.pinned[static_cast<std::size_t>(free[j])];
  };
  std::vector<int> pinned_slots, fitted_slots;
  for (int j = 0; j < NF; ++j) (pinned(j) ? pinned_slots : fitted_slots).push_back(j);
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
      functor.viscous[k] = scales_with_viscosity(setup.kind, static_cast<std::size_t>(k));
    }
    if (!data.viscous_factors.empty()) functor.viscous_factor = data.viscous_factors[r];
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
      const double margin = 1e-6 * (guess.upper[k] - guess.lower[k]);
      const auto inside = [&](double v) {
        return std::clamp(v, guess.lower[k] + margin, guess.upper[k] - margin);
      };
      double value = guess.nominal[k];
      if (pinned(j)) {  // held: the same value in every start
        thetas[static_cast<std::size_t>(start)][j] = value / guess.scale[k];
        continue;
      }
      if (start == 0 && !options.start.empty())
        value = inside(options.start[static_cast<std::size_t>(k)]);  // a given first start
      if (start > 0)  // perturbed around the nominal guess
        value = inside(value != 0.0 ? value * std::exp(0.7 * normal(rng))
                                    : 0.3 * guess.scale[k] * normal(rng));
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
  std::mutex progress_serial;      // one start at a time in the caller's progress callback
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
    for (const int j : fitted_slots) {
      problem.SetParameterLowerBound(theta.data(), j, guess.lower[free[j]] / guess.scale[free[j]]);
      problem.SetParameterUpperBound(theta.data(), j, guess.upper[free[j]] / guess.scale[free[j]]);
    }
    if (!pinned_slots.empty())
      problem.SetManifold(theta.data(), new ceres::SubsetManifold(NF, pinned_slots));
    ceres::Solver::Options so =
        greybox_solver_options(options.max_iterations, 50);  // trial steps into unstable regions
    so.num_threads = threads_per_start;
    IterationReport report(options.progress, progress_serial, iterations, clock_start,
                           "fitting " + fit.model, starts * options.max_iterations);
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
  fit.cost = best.cost;
  // Standard errors over the fitted slots only (a pinned slot is not a parameter of the fit).
  Eigen::MatrixXd jfit(m, static_cast<Eigen::Index>(fitted_slots.size()));
  for (std::size_t c = 0; c < fitted_slots.size(); ++c)
    jfit.col(static_cast<Eigen::Index>(c)) = jf.col(fitted_slots[c]);
  const std::vector<std::optional<double>> se_fitted = jacobian_standard_errors(jfit, res);
  std::vector<int> cluster_rows;
  for (const FitResidual<N, NF>& functor : functors)
    cluster_rows.push_back(static_cast<int>(functor.range.size()));
  const std::optional<ParameterCovariance> between = cluster_covariance(jfit, res, cluster_rows);
  const std::vector<std::optional<double>> se_between_fitted =
      between ? standard_errors_of(*between)
              : std::vector<std::optional<double>>(fitted_slots.size());
  std::vector<std::optional<double>> se(NF), se_between(NF);
  std::vector<int> fitted_column(NF, -1);  // slot -> column of jfit
  for (std::size_t c = 0; c < fitted_slots.size(); ++c) {
    se[fitted_slots[c]] = se_fitted[c];
    se_between[fitted_slots[c]] = se_between_fitted[c];
    fitted_column[fitted_slots[c]] = static_cast<int>(c);
  }

  const auto& specs = lumped::pheno_params(setup.kind);
  fit.params.clear();
  for (int k = 0; k < N; ++k) {
    FittedParameter fp;
    fp.name = specs[k].name;
    fp.unit = unit_string(specs[k].unit, setup);
    fp.value = guess.nominal[k] / guess.scale[k] * guess.scale[k];  // as the simulation sees it
    fp.fixed = guess.fixed[k] || (!guess.pinned.empty() && guess.pinned[k]);
    fit.params.push_back(fp);
  }
  for (const int j : fitted_slots) {
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
    for (const int a : fitted_slots)
      for (const int b : fitted_slots)
        if (se_between[a] && se_between[b])
          fit.covariance_between_recordings(free[a], free[b]) =
              between->matrix(fitted_column[a], fitted_column[b]) * guess.scale[free[a]] *
              guess.scale[free[b]];
  }
}

}  // namespace rheomag::identify::greybox_detail
