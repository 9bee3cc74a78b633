#include "magnetostatics/local_newton.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <numeric>

namespace rheomag::magnetostatics {

std::vector<int> concentrated_dofs(const Eigen::VectorXd& r, double fraction, int max_dofs) {
  const int n = static_cast<int>(r.size());
  const int count = std::min(n, max_dofs);
  if (count == 0) return {};
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::partial_sort(order.begin(), order.begin() + count, order.end(),
                    [&](int i, int j) { return std::abs(r[i]) > std::abs(r[j]); });
  const double target = fraction * r.squaredNorm();
  double held = 0.0;
  for (int k = 0; k < count; ++k) {
    held += r[order[k]] * r[order[k]];
    if (held >= target) return {order.begin(), order.begin() + k + 1};
  }
  return {};
}

int correct_locally(const PatchBuilder& build, const NewtonOptions& options, Eigen::VectorXd& r,
                    double& norm) {
  using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
  int steps = 0;
  for (int it = 0; it < options.local_iterations; ++it) {
    const std::vector<int> seeds =
        concentrated_dofs(r, options.local_fraction, options.local_max_dofs);
    if (seeds.empty()) break;
    // A local step pays when its patch is small against the whole problem: fewer rings when
    // the patch would exceed local_max_share of the unknowns, none when even one ring does.
    const double limit = options.local_max_share * static_cast<double>(r.size());
    std::unique_ptr<LocalPatch> patch;
    for (int layers = options.local_layers; layers >= 1; layers /= 2) {
      patch = build(seeds, layers);
      if (static_cast<double>(patch->unknowns()) <= limit) break;
    }
    if (!patch || static_cast<double>(patch->unknowns()) > limit) break;
    const int unknowns = patch->unknowns();
    const int rows = static_cast<int>(patch->rows().size());
    Eigen::VectorXd internal, trial_internal;
    SparseMatrix tangent;
    patch->assemble(internal, &tangent);
    Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower> cholesky(tangent);
    if (cholesky.info() != Eigen::Success) break;
    Eigen::VectorXd r_rows(rows);
    for (int k = 0; k < rows; ++k) r_rows[k] = r[patch->rows()[k]];
    const Eigen::VectorXd step = cholesky.solve(-r_rows.head(unknowns));
    const double slope = r_rows.head(unknowns).dot(step);
    if (!step.allFinite() || !(slope < 0.0)) break;
    const double rows_norm = r_rows.norm();
    const double potential = patch->potential();

    const Eigen::VectorXd start = patch->values();
    double alpha = 1.0;
    bool accepted = false;
    Eigen::VectorXd trial_rows;
    for (int k = 0; k <= options.max_backtracks; ++k, alpha *= 0.5) {
      patch->set_values(start + alpha * step);
      patch->assemble(trial_internal, nullptr);
      trial_rows = r_rows + (trial_internal - internal);  // the source is unchanged
      const double trial_norm = trial_rows.norm();
      if (!std::isfinite(trial_norm)) continue;
      if (trial_norm <= (1.0 - options.sufficient_decrease * alpha) * rows_norm ||
          patch->potential() <= potential + options.sufficient_decrease * alpha * slope) {
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      patch->set_values(start);
      break;
    }
    for (int k = 0; k < rows; ++k) r[patch->rows()[k]] = trial_rows[k];
    const double previous = norm;
    norm = r.norm();
    ++steps;
    // Another local step only after one that paid: at least halved |R| (a global step is then
    // the better use of the time).
    if (norm > 0.5 * previous) break;
  }
  return steps;
}

}  // namespace rheomag::magnetostatics
