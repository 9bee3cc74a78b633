#pragma once
// Discrete output-error models y = B(q)/F(q) u + e (single input), estimated by the simplified
// refined instrumental-variable method (SRIV, Young): ARX start, then prefiltering by 1/F and
// instruments from the noise-free auxiliary model output. Used to initialise tf and hw.

#include <Eigen/Dense>

namespace rheomag::identify {

/// A discrete OE model: F = 1 + f1 q^-1 + ... + f_nf q^-nf, B = b1 q^-nk + ... + b_nb q^-(nk+nb-1).
struct DiscreteOe {
  Eigen::VectorXd f;  ///< f1..f_nf
  Eigen::VectorXd b;  ///< b1..b_nb
  int nk = 1;         ///< input delay [samples]

  /// Noise-free output B/F u from zero initial conditions.
  Eigen::VectorXd simulate(const Eigen::VectorXd& u) const;
};

/// Filters x by B(q)/A(q) with A = 1 + a1 q^-1 + ..., B = b0 + b1 q^-1 + ... (zero initial state).
Eigen::VectorXd filter(const Eigen::VectorXd& b, const Eigen::VectorXd& a_tail,
                       const Eigen::VectorXd& x);

/// Moves the roots of 1 + f1 z^-1 + ... outside the unit circle to their mirror images 1/conj(z)
/// (shrunk to radius <= max_radius); returns the stabilised f1..f_nf.
Eigen::VectorXd stabilise(const Eigen::VectorXd& f, double max_radius = 0.999);

/// SRIV estimate of a single-input OE model of orders nb, nf, nk from u, y.
DiscreteOe fit_oe_sriv(const Eigen::VectorXd& u, const Eigen::VectorXd& y, int nb, int nf, int nk,
                       int iterations = 20);

}  // namespace rheomag::identify
