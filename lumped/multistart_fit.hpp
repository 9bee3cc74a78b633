#pragma once
// Pieces shared by the grey-box fits (greybox.cpp, valve_chain_fit.cpp): the Ceres solver settings,
// keeping the best of several starts, and the Jacobian at the optimum for standard errors.

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <exception>
#include <limits>
#include <thread>
#include <vector>

#include "lumped/metrics.hpp"

namespace rheomag::lumped {

/// Ceres settings of a grey-box fit: bounded Levenberg-Marquardt trust region, dense QR, one
/// thread, silent; `max_invalid_steps` trial steps may fail (unstable parameter regions).
inline ceres::Solver::Options greybox_solver_options(int max_iterations, int max_invalid_steps) {
  ceres::Solver::Options so;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = max_iterations;
  so.function_tolerance = 1e-10;
  so.parameter_tolerance = 1e-10;
  so.num_threads = 1;
  so.max_num_consecutive_invalid_steps = max_invalid_steps;
  so.logging_type = ceres::SILENT;
  return so;
}

/// Threads for the starts of a multi-start fit: `requested` if positive, else the machine's cores.
inline unsigned fit_threads(int requested) {
  if (requested > 0) return static_cast<unsigned>(requested);
  return std::max(1u, std::thread::hardware_concurrency());
}

/// Calls solve(i) for every start i < count on up to `threads` threads (each start once; the
/// starts must not share mutable state); rethrows the first exception a start threw.
template <class Solve>
void for_each_start(std::size_t count, unsigned threads, const Solve& solve) {
  const std::size_t workers = std::min<std::size_t>(std::max(1u, threads), count);
  if (workers <= 1) {
    for (std::size_t i = 0; i < count; ++i) solve(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> errors(count);
  const auto work = [&] {
    for (std::size_t i = next++; i < count; i = next++) {
      try {
        solve(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

/// The lowest-cost start of a multi-start fit.
template <int N>
struct BestStart {
  std::array<double, N> theta{};
  double cost = std::numeric_limits<double>::infinity();
  int start = 0;
  bool converged = false;
  /// Keeps `theta` (start number `start`) if the solve left a finite, lower cost. A FAILURE
  /// termination still leaves the last accepted iterate in theta; cost < 0 means no evaluation.
  void offer(const ceres::Solver::Summary& summary, const std::array<double, N>& candidate,
             int start_number) {
    if (summary.final_cost >= 0.0 && std::isfinite(summary.final_cost) &&
        summary.final_cost < cost) {
      cost = summary.final_cost;
      theta = candidate;
      start = start_number;
      converged = summary.termination_type == ceres::CONVERGENCE;
    }
  }
  /// True if some start gave a finite simulation.
  bool found() const { return std::isfinite(cost); }
};

/// Residuals and Jacobian (m x N, row-major) of an automatically differentiated `functor` at the
/// N parameters theta.
template <class Functor, int N>
void residual_jacobian(const Functor& functor, int m, const double* theta,
                       Eigen::Matrix<double, Eigen::Dynamic, N, Eigen::RowMajor>& jacobian,
                       Eigen::VectorXd& residuals) {
  jacobian.resize(m, N);
  residuals.resize(m);
  ceres::AutoDiffCostFunction<Functor, ceres::DYNAMIC, N> cost(new Functor(functor), m);
  const double* params[] = {theta};
  double* jacs[] = {jacobian.data()};
  cost.Evaluate(params, residuals.data(), jacs);
}

/// rms of y - yhat over the samples of `range` (the fit's residual standard deviation).
inline double rms_residual(const std::vector<double>& y, const std::vector<double>& yhat,
                           SampleRange range) {
  double ss = 0.0;
  for (std::size_t i = range.begin; i < range.end; ++i) ss += (y[i] - yhat[i]) * (y[i] - yhat[i]);
  return std::sqrt(ss / static_cast<double>(range.size()));
}

}  // namespace rheomag::lumped
