#include "identify/least_squares.hpp"

#include <ceres/ceres.h>
#include <glog/logging.h>

#include "core/error.hpp"

namespace rheomag::identify {

namespace {

/// Adapts a ResidualFunction to Ceres' dynamic numeric-diff interface (one parameter block).
struct ResidualAdapter {
  const ResidualFunction* function;
  std::ptrdiff_t parameters;
  std::ptrdiff_t residuals;

  bool operator()(double const* const* blocks, double* out) const {
    const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(blocks[0], parameters);
    Eigen::VectorXd r(residuals);
    if (!(*function)(x, r) || r.size() != residuals || !r.allFinite()) return false;
    Eigen::Map<Eigen::VectorXd>(out, residuals) = r;
    return true;
  }
};

}  // namespace

LeastSquaresResult minimise_residual(const ResidualFunction& residual, const Eigen::VectorXd& x0,
                                     std::ptrdiff_t residual_count, int max_iterations) {
  Eigen::VectorXd r0(residual_count);
  if (!residual(x0, r0) || !r0.allFinite())
    throw InputError("least-squares start point gives undefined residuals");
  LeastSquaresResult result;
  result.x = x0;
  auto* cost = new ceres::DynamicNumericDiffCostFunction<ResidualAdapter, ceres::CENTRAL>(
      new ResidualAdapter{&residual, x0.size(), residual_count});
  cost->AddParameterBlock(static_cast<int>(x0.size()));
  cost->SetNumResiduals(static_cast<int>(residual_count));
  ceres::Problem problem;
  problem.AddResidualBlock(cost, nullptr, result.x.data());
  ceres::Solver::Options options;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = max_iterations;
  options.function_tolerance = 1e-10;
  options.parameter_tolerance = 1e-10;
  options.logging_type = ceres::SILENT;
  options.num_threads = 1;
  ceres::Solver::Summary summary;
  // A start where the Jacobian cannot be evaluated is reported through the summary (and handled
  // by the caller); keep Ceres' glog message about it off the CLI's stderr.
  const int log_level = FLAGS_minloglevel;
  FLAGS_minloglevel = google::GLOG_FATAL;
  ceres::Solve(options, &problem, &summary);
  FLAGS_minloglevel = log_level;
  result.cost = summary.final_cost;
  result.iterations = static_cast<int>(summary.iterations.size());
  result.converged = summary.termination_type == ceres::CONVERGENCE;
  return result;
}

}  // namespace rheomag::identify
