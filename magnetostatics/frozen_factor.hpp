#pragma once
// A Cholesky factorisation kept after its solver has moved on: the tangent at one converged
// state, to solve nearby systems with (the quasi-static table's finite-difference neighbours,
// transient/quasi_static.hpp).

#include <Eigen/CholmodSupport>
#include <Eigen/Core>
#include <cstddef>

#include "magnetostatics/assembly.hpp"

namespace rheomag::magnetostatics {

/// CHOLMOD's supernodal LL^T as Eigen wraps it, with its factor readable (to copy it).
class SupernodalCholesky : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
 public:
  /// The factor of the last analysis or factorisation; null before the analysis.
  const cholmod_factor* factor() const { return m_cholmodFactor; }
};

/// An owned copy of a numeric CHOLMOD factorisation of a symmetric positive definite matrix,
/// independent of the solver that made it. Not for use from two threads at once.
class FrozenFactor {
 public:
  /// Copies `factor`; std::bad_alloc when CHOLMOD runs out of memory.
  explicit FrozenFactor(const cholmod_factor& factor);
  ~FrozenFactor();
  FrozenFactor(const FrozenFactor&) = delete;
  FrozenFactor& operator=(const FrozenFactor&) = delete;

  /// Rows of the factorised matrix.
  int size() const { return static_cast<int>(factor_->n); }
  /// Memory held by the factor's values and indices [bytes].
  std::size_t bytes() const;
  /// x = K^-1 b for the factorised K. ConvergenceError when CHOLMOD fails or x is not finite.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

 private:
  mutable cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
};

}  // namespace rheomag::magnetostatics
