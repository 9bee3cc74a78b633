// rosenbrock4 with dense output on a scaled copy of the system; finite-difference Jacobian.

#include "lumped/ode.hpp"

#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace rheomag::lumped {

namespace odeint = boost::numeric::odeint;
using UVector = boost::numeric::ublas::vector<double>;
using UMatrix = boost::numeric::ublas::matrix<double>;

namespace {

/// The system in scaled states xi = x / scale, as odeint wants it.
struct ScaledSystem {
  const OdeSystem& sys;
  std::vector<double> scale;
  mutable std::vector<double> x, dx;

  void operator()(const UVector& xi, UVector& dxi, double t) const {
    const std::size_t n = scale.size();
    for (std::size_t k = 0; k < n; ++k) x[k] = xi[k] * scale[k];
    sys.derivatives(t, x.data(), dx.data());
    for (std::size_t k = 0; k < n; ++k) dxi[k] = dx[k] / scale[k];
  }
};

/// Forward-difference Jacobian and time derivative of a ScaledSystem.
struct ScaledJacobian {
  const ScaledSystem& f;
  void operator()(const UVector& xi, UMatrix& jac, double t, UVector& dfdt) const {
    const std::size_t n = xi.size();
    UVector f0(n), f1(n), xp(xi);
    f(xi, f0, t);
    for (std::size_t j = 0; j < n; ++j) {
      const double h = 1e-7 * std::max(1.0, std::abs(xi[j]));
      xp[j] = xi[j] + h;
      f(xp, f1, t);
      xp[j] = xi[j];
      for (std::size_t i = 0; i < n; ++i) jac(i, j) = (f1[i] - f0[i]) / h;
    }
    const double ht = 1e-8 * std::max(1.0, std::abs(t));
    f(xi, f1, t + ht);
    for (std::size_t i = 0; i < n; ++i) dfdt[i] = (f1[i] - f0[i]) / ht;
  }
};

}  // namespace

std::vector<std::vector<double>> integrate_stiff(const OdeSystem& system, std::vector<double> x0,
                                                 const std::vector<double>& times,
                                                 const IntegratorOptions& options) {
  const std::size_t n = system.state_size();
  std::vector<std::vector<double>> out;
  out.reserve(times.size());
  if (times.empty()) return out;
  if (n == 0) {
    out.assign(times.size(), std::vector<double>{});
    return out;
  }
  ScaledSystem scaled{system, system.state_scales(), std::vector<double>(n),
                      std::vector<double>(n)};
  for (double& s : scaled.scale)
    if (!(s > 0.0) || !std::isfinite(s)) s = 1.0;
  ScaledJacobian jacobian{scaled};
  UVector xi(n);
  for (std::size_t k = 0; k < n; ++k) xi[k] = x0.at(k) / scaled.scale[k];

  double span = times.back() - times.front();
  double dt0 = times.size() > 1 ? std::min(1e-4 * span, times[1] - times[0]) : 1e-6;
  if (options.max_step > 0.0) dt0 = std::min(dt0, options.max_step);
  using Controller = odeint::rosenbrock4_controller<odeint::rosenbrock4<double>>;
  odeint::rosenbrock4_dense_output<Controller> stepper(
      Controller(options.abs_tol, options.rel_tol, options.max_step));
  auto observer = [&](const UVector& state, double t) {
    std::vector<double> x(n);
    for (std::size_t k = 0; k < n; ++k) {
      x[k] = state[k] * scaled.scale[k];
      if (!std::isfinite(x[k]))
        throw ConvergenceError("stiff integrator: state " + std::to_string(k) +
                               " is not finite at t = " + std::to_string(t) + " s");
    }
    out.push_back(std::move(x));
  };
  try {
    odeint::integrate_times(stepper, std::make_pair(std::cref(scaled), std::cref(jacobian)), xi,
                            times.begin(), times.end(), dt0, observer,
                            odeint::max_step_checker(100000));
  } catch (const odeint::odeint_error& e) {
    throw ConvergenceError(std::string("stiff integrator (rosenbrock4) failed: ") + e.what());
  }
  return out;
}

}  // namespace rheomag::lumped
