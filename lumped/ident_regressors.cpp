#include "lumped/ident_regressors.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "mesh/error.hpp"

namespace rheomag::lumped {

void fill_regressor(const Eigen::VectorXd& y_history, const Eigen::MatrixXd& u, std::ptrdiff_t k,
                    const LagOrders& orders, Eigen::Ref<Eigen::VectorXd> phi) {
  int col = 0;
  for (int i = 1; i <= orders.na; ++i) phi(col++) = y_history(k - i);
  for (std::ptrdiff_t j = 0; j < u.cols(); ++j)
    for (int i = 0; i < orders.nb; ++i) phi(col++) = u(k - orders.nk - i, j);
}

void regressor_matrix(const IoData& data, const LagOrders& orders, Eigen::MatrixXd& phi,
                      Eigen::VectorXd& target) {
  const std::ptrdiff_t start = orders.max_lag();
  const std::ptrdiff_t rows = data.size() - start;
  const int cols = orders.size(data.inputs());
  if (rows <= cols)
    throw InputError("too few samples (" + std::to_string(data.size()) + ") for " +
                     std::to_string(cols) + " regressors with lag " + std::to_string(start));
  phi.resize(rows, cols);
  target = data.y.tail(rows);
  Eigen::VectorXd row(cols);
  for (std::ptrdiff_t k = start; k < data.size(); ++k) {
    fill_regressor(data.y, data.u, k, orders, row);
    phi.row(k - start) = row.transpose();
  }
}

Eigen::VectorXd run_regression_model(const IoData& data, const LagOrders& orders,
                                     const std::function<double(const Eigen::VectorXd&)>& f,
                                     EvalMode mode) {
  const std::ptrdiff_t n = data.size();
  const std::ptrdiff_t start = std::min<std::ptrdiff_t>(orders.max_lag(), n);
  Eigen::VectorXd out = data.y;
  if (n == 0) return out;
  const double centre = 0.5 * (data.y.maxCoeff() + data.y.minCoeff());
  const double bound = 1e3 * std::max(data.y.maxCoeff() - data.y.minCoeff(), 1e-300);
  Eigen::VectorXd phi(orders.size(data.inputs()));
  const Eigen::VectorXd& history = mode == EvalMode::simulation ? out : data.y;
  for (std::ptrdiff_t k = start; k < n; ++k) {
    fill_regressor(history, data.u, k, orders, phi);
    double value = f(phi);
    if (!std::isfinite(value)) value = centre + bound;
    out(k) = std::clamp(value, centre - bound, centre + bound);
  }
  return out;
}

}  // namespace rheomag::lumped
