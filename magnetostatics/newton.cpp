#include "magnetostatics/newton.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/error.hpp"

namespace rheomag::magnetostatics {
namespace {

[[noreturn]] void fail(const std::string& why, int iteration, double relative, double tolerance) {
  std::ostringstream msg;
  msg << "Newton iteration did not converge: " << why << " after " << iteration
      << " iteration(s); relative residual reached " << relative << " (tolerance " << tolerance
      << ")";
  throw ConvergenceError(msg.str());
}

}  // namespace

NewtonReport newton_solve(NonlinearSystem& system, Eigen::VectorXd& x, double scale,
                          const NewtonOptions& options) {
  NewtonReport report;
  if (scale == 0.0) {
    x.setZero();
    report.residual_history.push_back(0.0);
    return report;
  }
  Eigen::VectorXd r, trial_r, trial;
  double norm = system.residual(x, r);
  report.residual_history.push_back(norm / scale);
  for (int it = 0;; ++it) {
    if (!std::isfinite(norm) || norm > options.divergence_factor * scale) {
      fail("the residual diverged", it, norm / scale, options.relative_tolerance);
    }
    if (norm <= options.relative_tolerance * scale) return report;
    if (it == options.max_iterations) {
      fail("maximum number of iterations reached", it, norm / scale, options.relative_tolerance);
    }
    system.factorize_jacobian(x);
    const double relative = norm / scale;
    double needed = 0.0;  // the loosest forcing that still ends below guard * tol, if any
    if (it > 0 && options.oversolve_guard > 0.0) {
      // The step leaves eta rho of linear error plus the nonlinear remainder K rho^2, with K
      // taken from the last step (rho_k / rho_{k-1}^2: an overestimate while the linear error
      // dominated, so the guard errs on the side of solving more).
      const double previous = report.residual_history[static_cast<std::size_t>(it) - 1];
      const double remainder = relative / (previous * previous) * relative * relative;
      needed = (options.oversolve_guard * options.relative_tolerance - remainder) / relative;
    }
    const double forcing = std::min(options.max_forcing, std::max(relative, needed));
    const Eigen::VectorXd step = system.solve_jacobian(-r, forcing);
    double alpha = 1.0, trial_norm = 0.0;
    bool accepted = false;
    // Energy test: E is convex and R = grad E, so R.dx < 0 for a descent direction; its value far
    // from the solution is what |R| cannot tell (a few saturated corner dofs can hold most of
    // |R| while the step lowers the energy everywhere else).
    const double slope = r.dot(step);
    double energy = std::numeric_limits<double>::quiet_NaN();
    bool has_energy = slope < 0.0;
    for (int k = 0; k <= options.max_backtracks; ++k, alpha *= 0.5) {
      trial = x + alpha * step;
      trial_norm = system.residual(trial, trial_r);
      if (!std::isfinite(trial_norm)) continue;
      if (trial_norm <= (1.0 - options.sufficient_decrease * alpha) * norm) {
        accepted = true;
        break;
      }
      if (has_energy && std::isnan(energy)) {
        energy = system.energy(x);
        has_energy = std::isfinite(energy);
      }
      if (has_energy &&
          system.energy(trial) <= energy + options.sufficient_decrease * alpha * slope) {
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      fail("the line search found no decrease of the residual", it + 1, norm / scale,
           options.relative_tolerance);
    }
    x.swap(trial);
    r.swap(trial_r);
    norm = trial_norm;
    if (options.local_iterations > 0 && norm > options.relative_tolerance * scale) {
      report.local_steps += system.correct_locally(x, r, norm);
    }
    report.iterations = it + 1;
    report.step_lengths.push_back(alpha);
    report.residual_history.push_back(norm / scale);
    if (options.on_step) options.on_step(report.iterations, norm / scale);
  }
}

}  // namespace rheomag::magnetostatics
