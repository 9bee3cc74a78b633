// Standard errors from the Jacobian (Gauss-Newton covariance).

#include "lumped/standard_errors.hpp"

#include <algorithm>
#include <cmath>

namespace rheomag::lumped {

std::vector<std::optional<double>> jacobian_standard_errors(const Eigen::MatrixXd& jacobian,
                                                            const Eigen::VectorXd& residuals) {
  const auto m = jacobian.rows(), p = jacobian.cols();
  const double sigma2 =
      residuals.squaredNorm() / static_cast<double>(std::max<Eigen::Index>(1, m - p));
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(jacobian.transpose() * jacobian);
  const Eigen::VectorXd lambda = eig.eigenvalues();
  const double tol = 1e-12 * std::max(lambda.size() ? lambda.maxCoeff() : 0.0, 1e-300);
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(p, p);
  std::vector<bool> identifiable(static_cast<std::size_t>(p), true);
  for (Eigen::Index e = 0; e < p; ++e) {
    const Eigen::VectorXd v = eig.eigenvectors().col(e);
    if (lambda[e] > tol) {
      cov += v * v.transpose() / lambda[e];
    } else {
      for (Eigen::Index c = 0; c < p; ++c)
        if (std::abs(v[c]) > 0.1) identifiable[static_cast<std::size_t>(c)] = false;
    }
  }
  std::vector<std::optional<double>> se(static_cast<std::size_t>(p));
  for (Eigen::Index c = 0; c < p; ++c)
    if (identifiable[static_cast<std::size_t>(c)])
      se[static_cast<std::size_t>(c)] = std::sqrt(std::max(0.0, cov(c, c) * sigma2));
  return se;
}

}  // namespace rheomag::lumped
