#pragma once
// Standard errors of least-squares parameters from the Jacobian at the optimum: the classical
// ones (independent residuals) and the cluster-robust ones (residuals correlated within a cluster).

#include <Eigen/Dense>
#include <optional>
#include <vector>

namespace rheomag::identify {

/// Standard error of each column's parameter: cov = (J^T J)^-1 sigma^2, sigma^2 = |r|^2 / (m - p).
/// Eigen-directions of J^T J with eigenvalue < 1e-12 of the largest are not identifiable: every
/// parameter with a component > 0.1 along one gets no standard error (empty).
std::vector<std::optional<double>> jacobian_standard_errors(const Eigen::MatrixXd& jacobian,
                                                            const Eigen::VectorXd& residuals);

/// A parameter covariance matrix and which parameters it identifies (jacobian_standard_errors'
/// rule).
struct ParameterCovariance {
  Eigen::MatrixXd matrix;
  std::vector<bool> identifiable;
};

/// The cluster-robust (CR1) covariance of cluster_standard_errors; empty with fewer than 2 clusters
/// or no more rows than parameters.
std::optional<ParameterCovariance> cluster_covariance(const Eigen::MatrixXd& jacobian,
                                                      const Eigen::VectorXd& residuals,
                                                      const std::vector<int>& cluster_rows);

/// Square roots of a covariance's diagonal where it identifies the parameter, else empty.
std::vector<std::optional<double>> standard_errors_of(const ParameterCovariance& covariance);

/// Cluster-robust (sandwich, CR1) standard errors: cov = (J^T J)^-1 (sum_g s_g s_g^T) (J^T J)^-1
/// g/(g-1) (m-1)/(m-p), s_g = J_g^T r_g the score of cluster g, whose rows are the next
/// cluster_rows[g] rows of J and r. With recordings as clusters it measures how far the
/// recordings disagree on each parameter, which the classical form (independent residuals)
/// misses when the residuals are correlated within a recording. Empty with fewer than 2 clusters
/// or where jacobian_standard_errors finds a parameter not identifiable.
std::vector<std::optional<double>> cluster_standard_errors(const Eigen::MatrixXd& jacobian,
                                                           const Eigen::VectorXd& residuals,
                                                           const std::vector<int>& cluster_rows);

}  // namespace rheomag::identify
