#include "transient/step_system.hpp"

#include "core/error.hpp"
#include "magnetostatics/cholmod_status.hpp"
#include "magnetostatics/preconditioned_cg.hpp"
#include "magnetostatics/serial_openmp.hpp"

namespace rheomag::transient {

using magnetostatics::ElementSet;
using magnetostatics::SparseMatrix;

SparseMatrix eddy_matrix(const magnetostatics::Assembler& assembler,
                         const std::vector<double>& sigma, const std::vector<double>& kappa) {
  SparseMatrix d = assembler.region_matrix(sigma, false);
  const SparseMatrix micro = assembler.region_matrix(kappa, true);  // the same pattern
  Eigen::Map<Eigen::VectorXd>(d.valuePtr(), d.nonZeros()) +=
      Eigen::Map<const Eigen::VectorXd>(micro.valuePtr(), micro.nonZeros());
  return d;
}

LinearPart linear_part(const magnetostatics::MagnetostaticSolver& statics) {
  LinearPart part;
  part.matrix = statics.assembler().pattern();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(statics.dofs().free_count());
  statics.assembler().assemble(statics.free_to_nodes(zero), part.offset, &part.matrix,
                               ElementSet::linear);
  return part;
}

StepSystem::StepSystem(const StepOperators& ops, Setup setup)
    : ops_(ops), setup_(std::move(setup)), n_(static_cast<int>(setup_.x0.size())) {
  if (setup_.jump) setup_.points = {{1.0, 1.0}};
  for (const auto& [s, w] : setup_.points) s_bar_ += w * s, w_sum_ += w;
}

Eigen::VectorXd StepSystem::nodes(const Eigen::VectorXd& x_free) const {
  return ops_.statics->free_to_nodes(x_free);
}

double StepSystem::mean_current(const Eigen::VectorXd& x) const {
  if (!setup_.voltage) return setup_.value;
  return setup_.i0 + s_bar_ * (x[n_] - setup_.i0);
}

double StepSystem::field_work(const Eigen::VectorXd& x) {
  if (residual_x_.size() != x.size() || residual_x_ != x) {
    Eigen::VectorXd r;
    residual(x, r);
  }
  return field_work_;
}

double StepSystem::residual(const Eigen::VectorXd& x, Eigen::VectorXd& r) {
  if (residual_r_.size() == x.size() && residual_x_ == x) {  // the last one asked for
    r = residual_r_;
    return r.norm();
  }
  // The step matrix is assembled with the residual: Newton factorises at the x of its last
  // accepted residual, and a tangent costs little more than a residual in the same pass.
  const auto& assembler = ops_.statics->assembler();
  const Eigen::VectorXd delta = x.head(n_) - setup_.x0;
  const double i_bar = mean_current(x);
  r.resize(x.size());
  Eigen::VectorXd field = Eigen::VectorXd::Zero(n_);
  const SparseMatrix& pattern = assembler.pattern();
  if (k_.nonZeros() != pattern.nonZeros()) k_ = tangent_ = pattern;
  Eigen::Map<Eigen::VectorXd> values(k_.valuePtr(), k_.nonZeros());
  values.setZero();
  const Eigen::Map<const Eigen::VectorXd> t_values(tangent_.valuePtr(), tangent_.nonZeros());
  const ElementSet set = ops_.linear ? ElementSet::nonlinear : ElementSet::all;
  if (set == ElementSet::all || assembler.nonlinear()) {
    for (const auto& [s, w] : setup_.points) {
      assembler.assemble(nodes(setup_.x0 + s * delta), part_, &tangent_, set);
      field += w * part_;
      values += (w * s) * t_values;
    }
  }
  if (ops_.linear) {
    // The affine part at the points: sum_g w_g (c + K x_g) = w_sum c + K (w_sum x0 + s_bar delta).
    const LinearPart& lin = *ops_.linear;
    field += w_sum_ * lin.offset +
             lin.matrix.selfadjointView<Eigen::Lower>() * (w_sum_ * setup_.x0 + s_bar_ * delta);
    values +=
        s_bar_ * Eigen::Map<const Eigen::VectorXd>(lin.matrix.valuePtr(), lin.matrix.nonZeros());
  }
  field_work_ = field.dot(delta);
  field -= i_bar * *ops_.drive_source + *ops_.other_source;
  if (setup_.jump) {
    // Conducting dofs stay put: their equations are x = x0, their rows and columns the identity.
    const auto& frozen = *ops_.conducting;
    for (int d = 0; d < n_; ++d)
      if (frozen[d]) field[d] = delta[d];
    for (int col = 0; col < n_; ++col) {
      for (SparseMatrix::InnerIterator it(k_, col); it; ++it) {
        if (frozen[it.row()] || frozen[col]) it.valueRef() = it.row() == col ? 1.0 : 0.0;
      }
    }
  } else {
    const SparseMatrix& d = *ops_.damping;
    field += (d.selfadjointView<Eigen::Lower>() * delta) / setup_.h;
    values += Eigen::Map<const Eigen::VectorXd>(d.valuePtr(), d.nonZeros()) / setup_.h;
  }
  residual_x_ = x;
  r.head(n_) = field;
  if (setup_.voltage) {
    r[n_] = s_bar_ * (setup_.h * (setup_.value - setup_.resistance * mean_current(x)) -
                      ops_.drive_source->dot(delta));
  }
  residual_r_ = r;
  return r.norm();
}

void StepSystem::factorize() {
  StepOperators::Factor& kept = *ops_.factor;
  kept.valid = false;
  {
    const magnetostatics::SerialOpenMp serial;
    ops_.cholesky->factorize(k_);
  }
  ++factorizations_;
  magnetostatics::throw_if_out_of_memory(*ops_.cholesky);
  if (ops_.cholesky->info() != Eigen::Success)
    throw ConvergenceError(
        "CHOLMOD factorisation of the time-step matrix failed (not positive "
        "definite, " +
        std::to_string(n_) + " unknowns)");
  kept.values = Eigen::Map<const Eigen::VectorXd>(k_.valuePtr(), k_.nonZeros());
  kept.valid = true;
  reuse_ = false;
  if (setup_.voltage) {
    const magnetostatics::SerialOpenMp serial;
    kept.k_inv_f = ops_.cholesky->solve(*ops_.drive_source);
  }
}

void StepSystem::factorize_jacobian(const Eigen::VectorXd& x) {
  if (residual_x_.size() != x.size() || residual_x_ != x) {
    Eigen::VectorXd r;
    residual(x, r);
  }
  const StepOperators::Factor& kept = *ops_.factor;
  const Eigen::Map<const Eigen::VectorXd> values(k_.valuePtr(), k_.nonZeros());
  const double change = kept.valid ? (values - kept.values).norm() : 0.0;
  if (!kept.valid || change > kRefactorChange * kept.values.norm()) {
    factorize();
  } else {
    reuse_ = change > 0.0;  // equal values: the kept factor is this matrix's
  }
  // K^-1 F of a reused factor is solved in solve_jacobian, to that solve's tolerance.
  if (setup_.voltage && !reuse_) k_inv_f_ = ops_.factor->k_inv_f;
}

Eigen::VectorXd StepSystem::solve_k(const Eigen::VectorXd& rhs, double tolerance) {
  const magnetostatics::SerialOpenMp serial;
  if (reuse_) {
    Eigen::VectorXd x;
    const magnetostatics::CgResult cg =
        magnetostatics::preconditioned_cg(k_, *ops_.cholesky, rhs, tolerance,
                                          magnetostatics::MagnetostaticSolver::kReuseIterations, x);
    if (cg.converged && x.allFinite()) return x;
    factorize();  // the kept factor was too far from this matrix
    if (setup_.voltage) k_inv_f_ = ops_.factor->k_inv_f;
  }
  Eigen::VectorXd x = ops_.cholesky->solve(rhs);
  magnetostatics::throw_if_out_of_memory(*ops_.cholesky);
  if (ops_.cholesky->info() != Eigen::Success || !x.allFinite())
    throw ConvergenceError("CHOLMOD triangular solve of the time-step matrix failed");
  return x;
}

Eigen::VectorXd StepSystem::solve_jacobian(const Eigen::VectorXd& rhs, double tolerance) {
  // [[K, -s F], [-s F^T, -s^2 h R]] [dx; di] = [b1; b2] by the Schur complement on di:
  // dx = K^-1 b1 + s di K^-1 F, di = -(b2 + s F^T K^-1 b1) / (s^2 (F^T K^-1 F + h R)).
  Eigen::VectorXd u = solve_k(rhs.head(n_), tolerance);
  if (!setup_.voltage) return u;
  // With a reused factor, K^-1 F by CG too, as the kept factor's K_old^-1 F plus a correction
  // (its residual F - K K_old^-1 F is of the order of the change of K). Its error e_z adds
  // s di e_z to the first block's residual, so a tenth of the forcing tolerance keeps the Newton
  // step within its forcing.
  if (reuse_) {
    const Eigen::VectorXd& f = *ops_.drive_source;
    Eigen::VectorXd z = ops_.factor->k_inv_f;
    const Eigen::VectorXd r0 = f - k_.selfadjointView<Eigen::Lower>() * z;
    const double target = 0.1 * tolerance * f.norm(), r0_norm = r0.norm();
    if (r0_norm > target) z += solve_k(r0, target / r0_norm);
    if (!reuse_) {  // that CG failed and K was factorised: redo u with the new factor
      u = solve_k(rhs.head(n_), tolerance);
      z = ops_.factor->k_inv_f;
    }
    k_inv_f_ = std::move(z);
  }
  const Eigen::VectorXd& f = *ops_.drive_source;
  const double s = s_bar_;
  const double schur = s * s * (f.dot(k_inv_f_) + setup_.h * setup_.resistance);
  const double di = -(rhs[n_] + s * f.dot(u)) / schur;
  Eigen::VectorXd out(rhs.size());
  out.head(n_) = u + (s * di) * k_inv_f_;
  out[n_] = di;
  return out;
}

}  // namespace rheomag::transient
