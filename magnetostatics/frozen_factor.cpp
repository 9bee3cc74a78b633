#include "magnetostatics/frozen_factor.hpp"

#include <new>
#include <string>

#include "core/error.hpp"
#include "magnetostatics/serial_openmp.hpp"

namespace rheomag::magnetostatics {

FrozenFactor::FrozenFactor(const cholmod_factor& factor) {
  cholmod_start(&common_);
  // cholmod_copy_factor only reads its input; its C signature is not const.
  factor_ = cholmod_copy_factor(const_cast<cholmod_factor*>(&factor), &common_);
  if (!factor_) {
    cholmod_finish(&common_);
    throw std::bad_alloc();
  }
}

FrozenFactor::~FrozenFactor() {
  cholmod_free_factor(&factor_, &common_);
  cholmod_finish(&common_);
}

std::size_t FrozenFactor::bytes() const {
  const std::size_t n = factor_->n;
  if (factor_->is_super)
    return factor_->xsize * sizeof(double) + (factor_->ssize + 2 * n) * sizeof(int);
  return factor_->nzmax * (sizeof(double) + sizeof(int)) + 4 * n * sizeof(int);
}

Eigen::VectorXd FrozenFactor::solve(const Eigen::VectorXd& b) const {
  if (b.size() != size())
    throw ConvergenceError("frozen factorisation of " + std::to_string(size()) +
                           " unknowns given a right-hand side of " + std::to_string(b.size()));
  cholmod_dense rhs{};
  rhs.nrow = rhs.nzmax = rhs.d = static_cast<std::size_t>(b.size());
  rhs.ncol = 1;
  rhs.x = const_cast<double*>(b.data());  // read only
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  const SerialOpenMp serial;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, factor_, &rhs, &common_);
  if (!x) {
    if (common_.status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
    throw ConvergenceError("CHOLMOD triangular solve with a frozen factorisation failed");
  }
  Eigen::VectorXd out =
      Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(x->x), b.size());
  cholmod_free_dense(&x, &common_);
  if (!out.allFinite())
    throw ConvergenceError("CHOLMOD triangular solve with a frozen factorisation is not finite");
  return out;
}

}  // namespace rheomag::magnetostatics
