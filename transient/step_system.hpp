#pragma once
// The discrete equations of one time step, as a nonlinear system for the static solver's Newton
// iteration, and the Schur-complement solve of their Jacobian.

#include <Eigen/CholmodSupport>
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "magnetostatics/newton.hpp"
#include "magnetostatics/solver.hpp"

namespace rheomag::transient {

/// The linear materials' share of the step residual (triangles without a B-H curve and the
/// mixed boundary edges), assembled once per run: over the free dofs x it is affine,
/// r_lin(x) = offset + K x, with K their exact (constant) tangent.
struct LinearPart {
  magnetostatics::SparseMatrix matrix;  ///< K, lower triangle, the pattern of the tangent
  Eigen::VectorXd offset;               ///< r_lin at x = 0 (prescribed values, Robin sources)
};

/// D = integral sigma N_i N_j dV + integral kappa G_i . G_j dV over the free dofs (lower
/// triangle, the pattern of the tangent): the eddy currents' dissipation D dA/dt.
magnetostatics::SparseMatrix eddy_matrix(const magnetostatics::Assembler& assembler,
                                         const std::vector<double>& sigma,
                                         const std::vector<double>& kappa);

/// Assembles the linear part of `statics`' problem once.
LinearPart linear_part(const magnetostatics::MagnetostaticSolver& statics);

/// Matrices and sources shared by every step of a run (free dofs; matrices lower-triangular,
/// all with the pattern of the static tangent).
struct StepOperators {
  const magnetostatics::MagnetostaticSolver* statics = nullptr;
  /// The eddy-current matrix D = integral sigma N_i N_j dV + integral kappa G_i . G_j dV (the
  /// mass matrix and the laminations' micro-eddy term, summed once: see eddy_matrix).
  const magnetostatics::SparseMatrix* damping = nullptr;
  const Eigen::VectorXd* drive_source = nullptr;  ///< F: first circuit at 1 A
  const Eigen::VectorXd* other_source = nullptr;  ///< other circuits, held
  const std::vector<char>* conducting = nullptr;  ///< dofs that cannot jump
  /// The linear part, or null to assemble every triangle at every point (the reference).
  const LinearPart* linear = nullptr;
  Eigen::CholmodSupernodalLLT<magnetostatics::SparseMatrix, Eigen::Lower>* cholesky = nullptr;
  /// The factorised step matrix, kept across Newton iterations and steps: a matrix equal to it
  /// is solved directly, one within kRefactorChange by conjugate gradients preconditioned with
  /// it (the static solver's rule), any other is factorised.
  struct Factor {
    bool valid = false;
    Eigen::VectorXd values;   ///< values of the factorised matrix (pattern of the tangent)
    Eigen::VectorXd k_inv_f;  ///< K^-1 F of that factor (voltage drive)
  }* factor = nullptr;
};

/// One step from (x0, i0) at t to (x1, i1) at t + h of
///   M (x1 - x0) / h + sum_g w_g R(x0 + s_g (x1 - x0)) = F i_bar + F_other,
///   voltage drive:  V = R i_bar + F . (x1 - x0) / h,   i_bar = sum_g w_g i(s_g),
/// with i linear over the step and (s_g, w_g) the points of the scheme in the step (midpoint:
/// Gauss-Legendre, 1 point for linear materials, 3 otherwise; backward Euler: s = 1). The
/// unknowns are x1 (and i1 for a voltage drive, appended). The circuit row is scaled by
/// -s_bar h so that the Jacobian [[K, -s_bar F], [-s_bar F^T, -s_bar^2 h R]] is symmetric;
/// K = M / h + sum_g w_g s_g K_t(A_g) is SPD and factorised, the current eliminated by its
/// Schur complement -s_bar^2 (F^T K^-1 F + h R) < 0.
/// A `jump` step is the instantaneous response at t = 0 of a current step: the conducting dofs
/// stay at x0 and the others satisfy the static equation at the new current.
class StepSystem : public magnetostatics::NonlinearSystem {
 public:
  /// The step's data; `points` are (s_g, w_g) on [0, 1].
  struct Setup {
    Eigen::VectorXd x0;
    double i0 = 0.0;       ///< current at the start of the step [A]
    double h = 0.0;        ///< step [s] (ignored for a jump)
    bool voltage = false;  ///< the current is an unknown
    double value = 0.0;    ///< current [A] (current drive) or voltage [V]
    double resistance = 0.0;
    bool jump = false;
    std::vector<std::pair<double, double>> points;
  };
  StepSystem(const StepOperators& ops, Setup setup);

  double residual(const Eigen::VectorXd& x, Eigen::VectorXd& r) override;
  void factorize_jacobian(const Eigen::VectorXd& x) override;
  Eigen::VectorXd solve_jacobian(const Eigen::VectorXd& rhs, double tolerance) override;

  /// Mean current over the step for unknowns x (i_bar).
  double mean_current(const Eigen::VectorXd& x) const;
  /// The scheme's field work over the step for unknowns x [J]: sum_g w_g R(A_g) . (x1 - x0),
  /// the quadrature of integral H . dB dV along the step (W(x1) - W(x0) when it is exact).
  double field_work(const Eigen::VectorXd& x);
  /// Numeric factorisations done.
  int factorizations() const { return factorizations_; }
  /// Relative change of the step matrix's values since the last factorisation above which it
  /// is factorised again (as MagnetostaticSolver::kRefactorChange).
  static constexpr double kRefactorChange = magnetostatics::MagnetostaticSolver::kRefactorChange;
  /// Sum of w_g s_g (1/2 midpoint, 1 backward Euler).
  double s_bar() const { return s_bar_; }
  /// The step matrix K (lower triangle) of the last residual call.
  const magnetostatics::SparseMatrix& step_matrix() const { return k_; }

 private:
  Eigen::VectorXd nodes(const Eigen::VectorXd& x_free) const;
  void factorize();
  Eigen::VectorXd solve_k(const Eigen::VectorXd& rhs, double tolerance);
  const StepOperators& ops_;
  Setup setup_;
  int n_ = 0;
  double s_bar_ = 0.0;
  double w_sum_ = 0.0;              // sum of w_g (1 for every scheme)
  magnetostatics::SparseMatrix k_;  // step matrix at residual_x_ (assembled with the residual)
  magnetostatics::SparseMatrix tangent_;  // tangent at one point (storage kept across calls)
  Eigen::VectorXd part_;                  // residual at one point
  Eigen::VectorXd residual_x_;            // where k_ was assembled
  Eigen::VectorXd residual_r_;            // the residual there (returned again for that x)
  double field_work_ = 0.0;               // sum_g w_g R(A_g) . delta at residual_x_
  bool reuse_ = false;                    // solve with CG preconditioned by the kept factor
  Eigen::VectorXd k_inv_f_;               // K^-1 F (voltage drive)
  int factorizations_ = 0;
};

}  // namespace rheomag::transient
