// Newton's forcing terms with inexact linear solves: the oversolving guard keeps the last step's
// linear tolerance at what convergence needs (Kelley, Iterative Methods for Linear and Nonlinear
// Equations, SIAM 1995, section 6.3: eta >= 0.5 tau / |F|, less the nonlinear remainder), and
// convergence is unchanged.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "magnetostatics/newton.hpp"

namespace rheomag::magnetostatics {
namespace {

/// R(x) = A x + x^3 - b (a convex energy), whose linear solves return the worst step the forcing
/// allows: J dx = rhs + d with |d| = tolerance |rhs|, d along the slowest eigenvector of J.
class CubicSystem : public NonlinearSystem {
 public:
  CubicSystem() : a_(3, 3), b_(3) {
    a_ << 4, 1, 0, 1, 3, 1, 0, 1, 2;
    b_ << 20, -5, 12;
  }
  double residual(const Eigen::VectorXd& x, Eigen::VectorXd& r) override {
    r = a_ * x + x.array().cube().matrix() - b_;
    return r.norm();
  }
  void factorize_jacobian(const Eigen::VectorXd& x) override {
    jacobian_ = a_;
    jacobian_.diagonal() += (3.0 * x.array().square()).matrix();
  }
  Eigen::VectorXd solve_jacobian(const Eigen::VectorXd& rhs, double tolerance) override {
    tolerances.push_back(tolerance);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(jacobian_);
    const Eigen::VectorXd error = tolerance * rhs.norm() * eigen.eigenvectors().col(0);
    return jacobian_.ldlt().solve(rhs + error);
  }
  double scale() const { return b_.norm(); }
  std::vector<double> tolerances;  ///< the forcing term of every linear solve, in order

 private:
  Eigen::MatrixXd a_, jacobian_;
  Eigen::VectorXd b_;
};

NewtonReport solve_with_guard(double guard, CubicSystem& system) {
  NewtonOptions options;
  options.max_forcing = 0.1;
  options.local_iterations = 0;
  options.oversolve_guard = guard;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(3);
  return newton_solve(system, x, system.scale(), options);
}

TEST(NewtonForcing, LastStepIsNotSolvedBeyondWhatConvergenceNeeds) {
  CubicSystem guarded, unguarded;
  const NewtonReport with = solve_with_guard(0.5, guarded);
  const NewtonReport without = solve_with_guard(0.0, unguarded);
  const double tolerance = NewtonOptions{}.relative_tolerance;
  // Both converge (the reported residual is below the tolerance) in the same number of steps.
  EXPECT_LE(with.residual_history.back(), tolerance);
  EXPECT_LE(without.residual_history.back(), tolerance);
  EXPECT_EQ(with.iterations, without.iterations);
  ASSERT_GE(with.iterations, 3);
  // Without the guard the last forcing is the relative residual (eta = |R| / |R0|); with it,
  // (0.5 tol - K rho^2) / rho (Kelley's bound less the nonlinear remainder at the last step's
  // rate K) up to max_forcing, which here is looser: fewer CG iterations, the same convergence.
  const double last_residual = without.residual_history[without.iterations - 1];
  EXPECT_NEAR(unguarded.tolerances.back(), last_residual, 1e-12 * last_residual);
  const double rho = with.residual_history[with.iterations - 1];
  const double rate = rho / std::pow(with.residual_history[with.iterations - 2], 2);  // K
  const double needed = std::min(0.1, (0.5 * tolerance - rate * rho * rho) / rho);
  EXPECT_NEAR(guarded.tolerances.back(), needed, 1e-12 * needed);
  EXPECT_GT(guarded.tolerances.back(), 3.0 * unguarded.tolerances.back());
  // Before the last step the guard does not bind: the forcing terms are the same.
  for (int k = 0; k + 1 < with.iterations; ++k)
    EXPECT_DOUBLE_EQ(guarded.tolerances[k], unguarded.tolerances[k]) << "step " << k + 1;
}

}  // namespace
}  // namespace rheomag::magnetostatics
