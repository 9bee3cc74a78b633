// Standard errors from the Jacobian (Gauss-Newton covariance) and their cluster-robust (sandwich)
// form with each recording one cluster.

#include "identify/standard_errors.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rheomag::identify {

namespace {

/// (J^T J)^-1 on its identifiable eigen-directions, and which parameters are identifiable: an
/// eigenvalue < 1e-12 of the largest marks every parameter with a component > 0.1 along it.
struct NormalInverse {
  Eigen::MatrixXd inverse;
  std::vector<bool> identifiable;
};

NormalInverse normal_inverse(const Eigen::MatrixXd& jacobian) {
  const auto p = jacobian.cols();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(jacobian.transpose() * jacobian);
  const Eigen::VectorXd lambda = eig.eigenvalues();
  const double tol = 1e-12 * std::max(lambda.size() ? lambda.maxCoeff() : 0.0, 1e-300);
  NormalInverse n{Eigen::MatrixXd::Zero(p, p),
                  std::vector<bool>(static_cast<std::size_t>(p), true)};
  for (Eigen::Index e = 0; e < p; ++e) {
    const Eigen::VectorXd v = eig.eigenvectors().col(e);
    if (lambda[e] > tol) {
      n.inverse += v * v.transpose() / lambda[e];
    } else {
      for (Eigen::Index c = 0; c < p; ++c)
        if (std::abs(v[c]) > 0.1) n.identifiable[static_cast<std::size_t>(c)] = false;
    }
  }
  return n;
}

/// Square roots of the diagonal of `cov` where identifiable, else empty.
std::vector<std::optional<double>> diagonal_roots(const Eigen::MatrixXd& cov,
                                                  const std::vector<bool>& identifiable) {
  std::vector<std::optional<double>> se(identifiable.size());
  for (std::size_t c = 0; c < se.size(); ++c) {
    const auto i = static_cast<Eigen::Index>(c);
    if (identifiable[c]) se[c] = std::sqrt(std::max(0.0, cov(i, i)));
  }
  return se;
}

}  // namespace

std::vector<std::optional<double>> jacobian_standard_errors(const Eigen::MatrixXd& jacobian,
                                                            const Eigen::VectorXd& residuals) {
  const auto m = jacobian.rows(), p = jacobian.cols();
  const double sigma2 =
      residuals.squaredNorm() / static_cast<double>(std::max<Eigen::Index>(1, m - p));
  const NormalInverse n = normal_inverse(jacobian);
  return diagonal_roots(n.inverse * sigma2, n.identifiable);
}

std::optional<ParameterCovariance> cluster_covariance(const Eigen::MatrixXd& jacobian,
                                                      const Eigen::VectorXd& residuals,
                                                      const std::vector<int>& cluster_rows) {
  const auto m = jacobian.rows(), p = jacobian.cols();
  const auto g = static_cast<Eigen::Index>(cluster_rows.size());
  if (g < 2 || m <= p) return std::nullopt;
  Eigen::Index total = 0;
  for (const int rows : cluster_rows) total += rows;
  if (total != m)
    throw std::invalid_argument("cluster_standard_errors: cluster rows do not sum to J's rows");
  const NormalInverse n = normal_inverse(jacobian);
  Eigen::MatrixXd meat = Eigen::MatrixXd::Zero(p, p);
  Eigen::Index row = 0;
  for (const int rows : cluster_rows) {
    const Eigen::VectorXd score =
        jacobian.middleRows(row, rows).transpose() * residuals.segment(row, rows);
    meat += score * score.transpose();
    row += rows;
  }
  // CR1 small-sample factor: g / (g - 1) for the clusters, (m - 1) / (m - p) for the parameters.
  const double factor = static_cast<double>(g) / static_cast<double>(g - 1) *
                        static_cast<double>(m - 1) / static_cast<double>(m - p);
  return ParameterCovariance{n.inverse * meat * n.inverse * factor, n.identifiable};
}

std::vector<std::optional<double>> standard_errors_of(const ParameterCovariance& covariance) {
  return diagonal_roots(covariance.matrix, covariance.identifiable);
}

std::vector<std::optional<double>> cluster_standard_errors(const Eigen::MatrixXd& jacobian,
                                                           const Eigen::VectorXd& residuals,
                                                           const std::vector<int>& cluster_rows) {
  const std::optional<ParameterCovariance> covariance =
      cluster_covariance(jacobian, residuals, cluster_rows);
  if (!covariance)
    return std::vector<std::optional<double>>(static_cast<std::size_t>(jacobian.cols()));
  return standard_errors_of(*covariance);
}

}  // namespace rheomag::identify
