#pragma once
// Standard errors of least-squares parameters from the Jacobian at the optimum.

#include <Eigen/Dense>
#include <optional>
#include <vector>

namespace rheomag::lumped {

/// Standard error of each column's parameter: cov = (J^T J)^-1 sigma^2, sigma^2 = |r|^2 / (m - p).
/// Eigen-directions of J^T J with eigenvalue < 1e-12 of the largest are not identifiable: every
/// parameter with a component > 0.1 along one gets no standard error (empty).
std::vector<std::optional<double>> jacobian_standard_errors(const Eigen::MatrixXd& jacobian,
                                                            const Eigen::VectorXd& residuals);

}  // namespace rheomag::lumped
