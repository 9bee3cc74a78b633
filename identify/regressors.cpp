#include "identify/regressors.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace rheomag::identify {

namespace {

/// rms deviation from the mean, 1 for a constant signal.
double spread(const Eigen::VectorXd& v) {
  const double s = std::sqrt((v.array() - v.mean()).square().mean());
  return s > 0.0 ? s : 1.0;
}

}  // namespace

Standardisation Standardisation::of(const IoData& data) {
  Standardisation st;
  st.u_mean.resize(data.inputs());
  st.u_scale.resize(data.inputs());
  for (std::ptrdiff_t j = 0; j < data.inputs(); ++j) {
    st.u_mean(j) = data.u.col(j).mean();
    st.u_scale(j) = spread(data.u.col(j));
  }
  st.y_mean = data.y.mean();
  st.y_scale = spread(data.y);
  return st;
}

IoData Standardisation::apply(const IoData& data, const std::string& model) const {
  if (data.inputs() != u_mean.size())
    throw InputError(model + " model has " + std::to_string(u_mean.size()) + " drives, data has " +
                     std::to_string(data.inputs()));
  IoData out = data;
  for (std::ptrdiff_t j = 0; j < data.inputs(); ++j)
    out.u.col(j) = (data.u.col(j).array() - u_mean(j)) / u_scale(j);
  out.y = (data.y.array() - y_mean) / y_scale;
  return out;
}

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

}  // namespace rheomag::identify
