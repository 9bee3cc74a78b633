#pragma once
// Pieces shared by the grey-box fits (greybox.cpp, valve_chain_fit.cpp): the Ceres solver settings,
// keeping the best of several starts, and the Jacobian at the optimum for standard errors.

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <limits>
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
