#pragma once
// Newton's method with a backtracking line search on the residual norm or, for systems with a
// potential, on that energy; optional local corrections where the residual concentrates.

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <vector>

namespace rheomag::magnetostatics {

/// Settings of the Newton iteration (defaults documented in docs and echoed in results).
struct NewtonOptions {
  double relative_tolerance = 1e-8;   ///< converged when |R(x)| <= tol * |R(x = 0)|
  int max_iterations = 50;            ///< Newton steps before ConvergenceError
  int max_backtracks = 12;            ///< step halvings per line search (minimum step 2^-12)
  double sufficient_decrease = 1e-4;  ///< Armijo constant c: accept when |R| <= (1 - c alpha)|R0|
  double divergence_factor = 1e6;     ///< ConvergenceError when |R| > factor * |R(x = 0)|
  /// Linear solves may be inexact (iterative, with a reused factorisation as preconditioner):
  /// |J dx + R| <= eta |R| with eta = min(max_forcing, |R| / |R(x = 0)|), which keeps the
  /// convergence quadratic (eta = O(|R|)), but not below oversolve_guard's bound.
  double max_forcing = 1e-2;
  /// The forcing term is loosened up to (oversolve_guard * tol - K rho^2) / rho, rho = |R| / |R0|
  /// and K = rho_k / rho_{k-1}^2 the last step's quadratic rate: the last step's linear system is
  /// not solved beyond what convergence needs (Kelley's safeguard against oversolving, with the
  /// nonlinear remainder subtracted so that the step still converges; 0 turns it off).
  double oversolve_guard = 0.5;
  /// Local corrections after each Newton step (nonlinear elimination): when at most
  /// local_max_dofs dofs hold local_fraction of |R|^2 (a saturating corner), up to
  /// local_iterations Newton steps on those dofs grown by local_layers rings of elements, the rest
  /// held fixed. 0 disables them.
  int local_iterations = 3;
  double local_fraction = 0.9;  ///< share of |R|^2 that makes the residual "concentrated"
  int local_max_dofs = 500;     ///< at most this many seed dofs
  int local_layers = 4;         ///< rings of elements added around the seed dofs
  /// Largest patch as a share of all dofs (fewer rings, or no local step, beyond it).
  double local_max_share = 0.1;
  /// Called after each accepted step with the steps so far and the relative residual (progress
  /// of a long solve; optional).
  std::function<void(int steps, double relative_residual)> on_step;
};

/// What the iteration did.
struct NewtonReport {
  int iterations = 0;                    ///< Newton steps taken
  std::vector<double> residual_history;  ///< relative residual before the first and after each step
  std::vector<double> step_lengths;      ///< accepted line-search step per iteration
  int local_steps = 0;                   ///< local correction steps in all
};

/// A nonlinear system R(x) = 0 with a factorisable Jacobian.
class NonlinearSystem {
 public:
  virtual ~NonlinearSystem() = default;
  /// Residual R(x) into `r`; returns its Euclidean norm.
  virtual double residual(const Eigen::VectorXd& x, Eigen::VectorXd& r) = 0;
  /// Assembles and factorises the Jacobian at x (throws ConvergenceError if that fails).
  virtual void factorize_jacobian(const Eigen::VectorXd& x) = 0;
  /// Solves J dx = rhs for the Jacobian of the last factorize_jacobian call, to a relative
  /// residual `tolerance` or better.
  virtual Eigen::VectorXd solve_jacobian(const Eigen::VectorXd& rhs, double tolerance) = 0;
  /// A potential E(x) with R = grad E (convex for a monotone material law), or NaN when the
  /// system has none. The line search also accepts steps that decrease E sufficiently.
  virtual double energy(const Eigen::VectorXd& /*x*/) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  /// Local corrections after a Newton step: may change x where the residual r concentrates,
  /// keeping r = R(x) and norm = |r| up to date; returns the number of local steps (0: none).
  virtual int correct_locally(Eigen::VectorXd& /*x*/, Eigen::VectorXd& /*r*/, double& /*norm*/) {
    return 0;
  }
};

/// Solves R(x) = 0 from the initial x; a step x + alpha dx is accepted when it reduces |R| by the
/// Armijo factor or, for a system with energy, when E(x + alpha dx) <= E(x) + c alpha R.dx; `scale`
/// = |R(x = 0)| is the reference of the relative residual (if scale == 0 the solution is x = 0).
/// Throws ConvergenceError, with the relative residual reached, when the tolerance is not met
/// within max_iterations, when the line search cannot reduce the residual, or when the residual
/// exceeds divergence_factor * scale or is NaN.
NewtonReport newton_solve(NonlinearSystem& system, Eigen::VectorXd& x, double scale,
                          const NewtonOptions& options);

}  // namespace rheomag::magnetostatics
