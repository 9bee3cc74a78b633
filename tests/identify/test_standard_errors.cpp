// Standard errors of least-squares parameters (identify/standard_errors.hpp) against closed forms:
// the cluster-robust (CR1 sandwich) error of a mean over clusters, and with one cluster per row
// White's HC1 error of a straight line's slope (MacKinnon & White 1985).

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "identify/standard_errors.hpp"

namespace {

using rheomag::identify::cluster_standard_errors;
using rheomag::identify::jacobian_standard_errors;

// A mean fitted to three clusters: J is a column of ones, r = mean - y. CR1 closed form:
// var = g/(g-1) (m-1)/(m-1) sum_g (sum_{i in g} r_i)^2 / m^2. Tolerance: rounding, 1e-12 relative.
TEST(StandardErrors, ClusterRobustErrorOfAMeanMatchesItsClosedForm) {
  const std::vector<std::vector<double>> clusters = {
      {1.0, 1.2, 0.9, 1.1}, {2.0, 2.3, 1.8, 2.1, 2.2}, {0.2, 0.1, 0.4, 0.3, 0.0, 0.2}};
  std::vector<double> y;
  std::vector<int> rows;
  for (const auto& c : clusters) {
    y.insert(y.end(), c.begin(), c.end());
    rows.push_back(static_cast<int>(c.size()));
  }
  const auto m = static_cast<Eigen::Index>(y.size());
  double mean = 0.0;
  for (double v : y) mean += v;
  mean /= static_cast<double>(m);
  Eigen::MatrixXd j = Eigen::MatrixXd::Ones(m, 1);
  Eigen::VectorXd r(m);
  for (Eigen::Index i = 0; i < m; ++i) r[i] = mean - y[static_cast<std::size_t>(i)];
  double meat = 0.0;
  std::size_t at = 0;
  for (const auto& c : clusters) {
    double s = 0.0;
    for (std::size_t i = 0; i < c.size(); ++i) s += mean - y[at++];
    meat += s * s;
  }
  const double g = 3.0;
  const double expected = std::sqrt(g / (g - 1.0) * meat) / static_cast<double>(m);
  const auto se = cluster_standard_errors(j, r, rows);
  ASSERT_TRUE(se[0].has_value());
  EXPECT_NEAR(*se[0], expected, 1e-12 * expected);
  // The clusters' levels differ, so the clustered error is above the classical one (2.7x here).
  EXPECT_GT(*se[0], 2.0 * *jacobian_standard_errors(j, r)[0]);
}

// One cluster per row: CR1 is White's HC1. Slope of y = a + b x: var(b) = m/(m-2)
// sum (x_i - xbar)^2 r_i^2 / (sum (x_i - xbar)^2)^2. Tolerance 1e-10 relative.
TEST(StandardErrors, OneClusterPerRowIsWhitesHeteroscedasticError) {
  const std::vector<double> x = {0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.5};
  const std::vector<double> y = {0.1, 0.9, 2.2, 2.8, 4.4, 5.7, 8.9, 10.2};
  const auto m = static_cast<Eigen::Index>(x.size());
  double xbar = 0.0, ybar = 0.0;
  for (Eigen::Index i = 0; i < m; ++i) {
    xbar += x[static_cast<std::size_t>(i)] / static_cast<double>(m);
    ybar += y[static_cast<std::size_t>(i)] / static_cast<double>(m);
  }
  double sxx = 0.0, sxy = 0.0;
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto k = static_cast<std::size_t>(i);
    sxx += (x[k] - xbar) * (x[k] - xbar);
    sxy += (x[k] - xbar) * (y[k] - ybar);
  }
  const double b = sxy / sxx, a = ybar - b * xbar;
  Eigen::MatrixXd j(m, 2);
  Eigen::VectorXd r(m);
  double meat = 0.0;
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto k = static_cast<std::size_t>(i);
    j(i, 0) = 1.0;
    j(i, 1) = x[k];
    r[i] = a + b * x[k] - y[k];
    meat += (x[k] - xbar) * (x[k] - xbar) * r[i] * r[i];
  }
  const double expected =
      std::sqrt(static_cast<double>(m) / static_cast<double>(m - 2) * meat) / sxx;
  const auto se = cluster_standard_errors(j, r, std::vector<int>(x.size(), 1));
  ASSERT_TRUE(se[1].has_value());
  EXPECT_NEAR(*se[1], expected, 1e-10 * expected);
}

// Fewer than two clusters: no clustered error. A column that is a copy of another: neither is
// identifiable (as in jacobian_standard_errors). Rows that do not add up: a programming error.
TEST(StandardErrors, ClusterRobustErrorNeedsClustersAndIdentifiableParameters) {
  Eigen::MatrixXd j(4, 2);
  j << 1, 1, 1, 1, 1, 1, 1, 1;
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(4, -1.0, 1.0);
  EXPECT_FALSE(cluster_standard_errors(j.leftCols(1), r, {4})[0].has_value());
  const auto se = cluster_standard_errors(j, r, {2, 2});
  EXPECT_FALSE(se[0].has_value());
  EXPECT_FALSE(se[1].has_value());
  EXPECT_THROW(cluster_standard_errors(j, r, {2, 1}), std::invalid_argument);
}

}  // namespace
