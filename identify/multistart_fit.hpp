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
#include <memory>
#include <thread>
#include <vector>

#include "lumped/metrics.hpp"

namespace rheomag::identify {

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

/// A cost function of one parameter block that remembers its last evaluation: Ceres' bounded
/// trust region evaluates the Jacobian at the end of its projected line search and again when it
/// accepts that same point, and each evaluation is a full model simulation. Results are
/// bit-identical to the wrapped function's. Not thread-safe (one per Ceres problem).
class CachedCostFunction : public ceres::CostFunction {
 public:
  /// Takes ownership of `inner`, which must have exactly one parameter block.
  explicit CachedCostFunction(ceres::CostFunction* inner) : inner_(inner) {
    set_num_residuals(inner->num_residuals());
    *mutable_parameter_block_sizes() = inner->parameter_block_sizes();
    const int m = num_residuals(), n = parameter_block_sizes().front();
    params_.resize(static_cast<std::size_t>(n));
    residuals_.resize(static_cast<std::size_t>(m));
    jacobian_.resize(static_cast<std::size_t>(m) * static_cast<std::size_t>(n));
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const bool want_jacobian = jacobians != nullptr && jacobians[0] != nullptr;
    const bool same_point = valid_ && std::equal(params_.begin(), params_.end(), parameters[0]);
    if (!same_point || (want_jacobian && !has_jacobian_)) {
      std::copy(parameters[0], parameters[0] + params_.size(), params_.begin());
      double* jac[] = {jacobian_.data()};
      ok_ = inner_->Evaluate(parameters, residuals_.data(), want_jacobian ? jac : nullptr);
      valid_ = true;
      has_jacobian_ = want_jacobian;
    }
    if (!ok_) return false;
    std::copy(residuals_.begin(), residuals_.end(), residuals);
    if (want_jacobian) std::copy(jacobian_.begin(), jacobian_.end(), jacobians[0]);
    return true;
  }

 private:
  std::unique_ptr<ceres::CostFunction> inner_;
  mutable std::vector<double> params_, residuals_, jacobian_;
  mutable bool valid_ = false, has_jacobian_ = false, ok_ = false;
};

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
                           lumped::SampleRange range) {
  double ss = 0.0;
  for (std::size_t i = range.begin; i < range.end; ++i) ss += (y[i] - yhat[i]) * (y[i] - yhat[i]);
  return std::sqrt(ss / static_cast<double>(range.size()));
}

}  // namespace rheomag::identify
