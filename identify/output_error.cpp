#include "identify/output_error.hpp"

#include <algorithm>
#include <complex>
#include <string>
#include <unsupported/Eigen/Polynomials>
#include <vector>

#include "core/error.hpp"

namespace rheomag::identify {

Eigen::VectorXd filter(const Eigen::VectorXd& b, const Eigen::VectorXd& a_tail,
                       const Eigen::VectorXd& x) {
  const std::ptrdiff_t n = x.size();
  Eigen::VectorXd out(n);
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    double acc = 0.0;
    for (std::ptrdiff_t i = 0; i < b.size() && i <= k; ++i) acc += b(i) * x(k - i);
    for (std::ptrdiff_t i = 0; i < a_tail.size() && i < k; ++i) acc -= a_tail(i) * out(k - 1 - i);
    out(k) = acc;
  }
  return out;
}

Eigen::VectorXd DiscreteOe::simulate(const Eigen::VectorXd& u) const {
  Eigen::VectorXd num = Eigen::VectorXd::Zero(nk + b.size());
  num.tail(b.size()) = b;
  return filter(num, f, u);
}

Eigen::VectorXd stabilise(const Eigen::VectorXd& f, double max_radius) {
  if (f.size() == 0) return f;
  // z^n + f1 z^(n-1) + ... + fn, coefficients in increasing degree for Eigen's solver.
  Eigen::VectorXd coeffs(f.size() + 1);
  for (std::ptrdiff_t i = 0; i < f.size(); ++i) coeffs(i) = f(f.size() - 1 - i);
  coeffs(f.size()) = 1.0;
  Eigen::PolynomialSolver<double, Eigen::Dynamic> solver(coeffs);
  std::vector<std::complex<double>> roots(solver.roots().data(),
                                          solver.roots().data() + solver.roots().size());
  bool changed = false;
  for (auto& z : roots) {
    double r = std::abs(z);
    if (r > 1.0) {
      z = 1.0 / std::conj(z);
      r = 1.0 / r;
      changed = true;
    }
    if (r > max_radius) {
      z *= max_radius / r;
      changed = true;
    }
  }
  if (!changed) return f;
  std::vector<std::complex<double>> poly{1.0};  // highest power first
  for (const auto& z : roots) {
    poly.push_back(0.0);
    for (std::size_t i = poly.size() - 1; i > 0; --i) poly[i] -= z * poly[i - 1];
  }
  Eigen::VectorXd out(f.size());
  for (std::ptrdiff_t i = 0; i < f.size(); ++i) out(i) = poly[i + 1].real();
  return out;
}

namespace {

/// Regressor rows [-y(k-1..k-nf), u(k-nk..k-nk-nb+1)] for k >= start.
Eigen::MatrixXd oe_regressors(const Eigen::VectorXd& y, const Eigen::VectorXd& u, int nb, int nf,
                              int nk, std::ptrdiff_t start) {
  const std::ptrdiff_t rows = y.size() - start;
  Eigen::MatrixXd phi(rows, nf + nb);
  for (std::ptrdiff_t k = start; k < y.size(); ++k) {
    for (int i = 0; i < nf; ++i) phi(k - start, i) = -y(k - 1 - i);
    for (int i = 0; i < nb; ++i) phi(k - start, nf + i) = u(k - nk - i);
  }
  return phi;
}

}  // namespace

DiscreteOe fit_oe_sriv(const Eigen::VectorXd& u, const Eigen::VectorXd& y, int nb, int nf, int nk,
                       int iterations) {
  if (nb < 1 || nf < 0 || nk < 0) throw InputError("OE orders need nb >= 1, nf >= 0, nk >= 0");
  const std::ptrdiff_t start = std::max(nf, nb + nk - 1);
  if (y.size() - start <= 2 * (nb + nf))
    throw InputError("too few samples (" + std::to_string(y.size()) + ") for an OE model with " +
                     std::to_string(nb + nf) + " parameters");
  DiscreteOe model;
  model.nk = nk;
  // ARX start.
  {
    const Eigen::MatrixXd phi = oe_regressors(y, u, nb, nf, nk, start);
    const Eigen::VectorXd theta = phi.colPivHouseholderQr().solve(y.tail(phi.rows()));
    model.f = stabilise(theta.head(nf));
    model.b = theta.tail(nb);
  }
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(1);
  for (int it = 0; it < iterations; ++it) {
    const Eigen::VectorXd uf = filter(one, model.f, u);
    const Eigen::VectorXd yf = filter(one, model.f, y);
    const Eigen::VectorXd xf = filter(one, model.f, model.simulate(u));
    const Eigen::MatrixXd phi = oe_regressors(yf, uf, nb, nf, nk, start);
    const Eigen::MatrixXd zeta = oe_regressors(xf, uf, nb, nf, nk, start);
    const Eigen::VectorXd theta = (zeta.transpose() * phi)
                                      .colPivHouseholderQr()
                                      .solve(zeta.transpose() * yf.tail(phi.rows()));
    if (!theta.allFinite()) break;
    const Eigen::VectorXd f_new = stabilise(theta.head(nf));
    const double change = (f_new - model.f).norm() + (theta.tail(nb) - model.b).norm();
    const double size = model.f.norm() + model.b.norm() + 1e-300;
    model.f = f_new;
    model.b = theta.tail(nb);
    if (change < 1e-9 * size) break;
  }
  return model;
}

}  // namespace rheomag::identify
