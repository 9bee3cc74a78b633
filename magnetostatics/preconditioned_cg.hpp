#pragma once
// Conjugate gradients preconditioned by a Cholesky factorisation of a nearby matrix.

#include <Eigen/CholmodSupport>
#include <Eigen/Core>

#include "magnetostatics/assembly.hpp"

namespace rheomag::magnetostatics {

/// Outcome of preconditioned_cg.
struct CgResult {
  bool converged = false;  ///< |K x - b| <= tolerance |b| reached
  int iterations = 0;      ///< CG iterations (one preconditioner solve and product each)
};

/// Solves K x = b (K symmetric positive definite, lower triangle stored) by conjugate gradients
/// preconditioned with `factor` (a factorisation of a matrix close to K), from x = 0, to
/// |K x - b| <= tolerance |b|, or, when functional_tolerance > 0, until the error of b.x (by
/// which CG from 0 underestimates b.K^-1.b: r.K^-1.r, estimated with the factor as r.M^-1.r) is
/// at most functional_tolerance b.x. Gives up after max_iterations, or earlier, from the third
/// iteration on, when the mean residual reduction so far projects past max_iterations (a stale
/// factor then costs two or three iterations instead of max_iterations).
CgResult preconditioned_cg(const SparseMatrix& k,
                           const Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower>& factor,
                           const Eigen::VectorXd& b, double tolerance, int max_iterations,
                           Eigen::VectorXd& x, double functional_tolerance = 0.0);

}  // namespace rheomag::magnetostatics
