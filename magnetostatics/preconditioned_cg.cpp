#include "magnetostatics/preconditioned_cg.hpp"

#include <cmath>

namespace rheomag::magnetostatics {

CgResult preconditioned_cg(const SparseMatrix& k,
                           const Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower>& factor,
                           const Eigen::VectorXd& b, double tolerance, int max_iterations,
                           Eigen::VectorXd& x, double functional_tolerance) {
  CgResult result;
  x.setZero(b.size());
  const double b_norm = b.norm();
  if (b_norm == 0.0) {
    result.converged = true;
    return result;
  }
  Eigen::VectorXd r = b, z = factor.solve(r), p = z, q(b.size());
  double rz = r.dot(z);
  while (result.iterations < max_iterations) {
    q.noalias() = k.selfadjointView<Eigen::Lower>() * p;
    const double pq = p.dot(q);
    if (!(pq > 0.0) || !std::isfinite(rz)) return result;
    const double alpha = rz / pq;
    x += alpha * p;
    r -= alpha * q;
    ++result.iterations;
    const double relative = r.norm() / b_norm;
    if (relative <= tolerance) {
      result.converged = true;
      return result;
    }
    const bool functional = functional_tolerance > 0.0;
    if (!functional && result.iterations >= 3) {
      // Mean reduction per iteration so far; give up if it cannot reach the tolerance in time.
      const double rate = std::pow(relative, 1.0 / result.iterations);
      if (!(rate < 1.0) ||
          result.iterations + std::log(tolerance / relative) / std::log(rate) > max_iterations) {
        return result;
      }
    }
    z = factor.solve(r);
    const double rz_next = r.dot(z);
    if (functional && rz_next <= functional_tolerance * std::abs(b.dot(x))) {
      result.converged = true;
      return result;
    }
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  return result;
}

}  // namespace rheomag::magnetostatics
