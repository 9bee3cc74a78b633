#pragma once
// Stiff integration of x' = f(t, x) with Boost.Odeint rosenbrock4 (dense output) at given times.

#include <cstddef>
#include <vector>

namespace rheomag::lumped {

/// A first-order ODE system x' = f(t, x) with typical state magnitudes for error control.
class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  /// Number of states.
  virtual std::size_t state_size() const = 0;
  /// Writes f(t, x) into dxdt (both of length state_size()).
  virtual void derivatives(double t, const double* x, double* dxdt) const = 0;
  /// Typical magnitude of each state (SI); tolerances apply to x / scale.
  virtual std::vector<double> state_scales() const = 0;
};

/// Tolerances of the stiff integrator (on states divided by their scales).
struct IntegratorOptions {
  double abs_tol = 1e-7;
  double rel_tol = 1e-6;
  double max_step = 0.0;  ///< [s] upper bound on the internal step; 0 = no bound
};

/// Integrates from `x0` at `times[0]` and returns the state at every entry of `times`
/// (strictly increasing), interpolated by rosenbrock4's dense output. The Jacobian is formed by
/// finite differences. Throws ConvergenceError if the step size collapses or a state is not finite.
std::vector<std::vector<double>> integrate_stiff(const OdeSystem& system, std::vector<double> x0,
                                                 const std::vector<double>& times,
                                                 const IntegratorOptions& options = {});

}  // namespace rheomag::lumped
