#pragma once
// Nonlinear least squares on a residual vector with Ceres (Levenberg-Marquardt, central-difference
// Jacobian): the simulation-error refinement shared by tf and hw.

#include <Eigen/Dense>
#include <functional>

namespace rheomag::identify {

/// Residuals r(x); returns false where r is undefined (e.g. an unstable model), so the step is
/// rejected.
using ResidualFunction = std::function<bool(const Eigen::VectorXd& x, Eigen::VectorXd& r)>;

/// Outcome of minimise_residual.
struct LeastSquaresResult {
  Eigen::VectorXd x;       ///< parameters at the end
  double cost = 0.0;       ///< 0.5 |r|^2 at x
  int iterations = 0;      ///< LM iterations taken
  bool converged = false;  ///< Ceres reported convergence (not just the iteration cap)
};

/// Minimises 0.5 |r(x)|^2 from x0 with `residual_count` residuals; r(x0) must be defined
/// (InputError otherwise).
LeastSquaresResult minimise_residual(const ResidualFunction& residual, const Eigen::VectorXd& x0,
                                     std::ptrdiff_t residual_count, int max_iterations = 100);

}  // namespace rheomag::identify
