#include "identify/arx.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace rheomag::identify {

ArxModel::ArxModel(LagOrders orders, Eigen::VectorXd theta, std::ptrdiff_t inputs)
    : orders_(orders), theta_(std::move(theta)), inputs_(inputs) {}

std::string ArxModel::name() const {
  return "arx:" + std::to_string(orders_.na) + "," + std::to_string(orders_.nb) + "," +
         std::to_string(orders_.nk);
}

std::vector<NamedValue> ArxModel::params() const {
  std::vector<NamedValue> out{{"na", orders_.na}, {"nb", orders_.nb}, {"nk", orders_.nk}};
  const Eigen::VectorXd av = a();
  for (int i = 0; i < orders_.na; ++i) out.emplace_back(numbered("a", i + 1), av(i));
  for (std::ptrdiff_t j = 0; j < inputs_; ++j) {
    const Eigen::VectorXd bv = b(j);
    const std::string prefix = inputs_ > 1 ? numbered("b", j + 1) + "_" : "b";
    for (int i = 0; i < orders_.nb; ++i) out.emplace_back(numbered(prefix, i + 1), bv(i));
  }
  return out;
}

Eigen::VectorXd ArxModel::run(const IoData& data, EvalMode mode) const {
  return run_regression_model(
      data, orders_, [this](const Eigen::VectorXd& phi) { return theta_.dot(phi); }, mode);
}

namespace {

void check_orders(const LagOrders& orders) {
  if (orders.na < 0 || orders.nb < 1 || orders.nk < 0)
    throw InputError("ARX orders need na >= 0, nb >= 1, nk >= 0 (got " + std::to_string(orders.na) +
                     "," + std::to_string(orders.nb) + "," + std::to_string(orders.nk) + ")");
}

Eigen::VectorXd least_squares(const Eigen::MatrixXd& phi, const Eigen::VectorXd& target) {
  return phi.colPivHouseholderQr().solve(target);
}

}  // namespace

ArxModel fit_arx(const IoData& data, const LagOrders& orders) {
  check_orders(orders);
  Eigen::MatrixXd phi;
  Eigen::VectorXd target;
  regressor_matrix(data, orders, phi, target);
  return ArxModel(orders, least_squares(phi, target), data.inputs());
}

std::vector<OrderScore> rank_arx_orders(const IoData& data, const ArxGrid& grid,
                                        OrderCriterion criterion) {
  const int common_start = std::max(grid.na_max, grid.nb_max + grid.nk_max - 1);
  std::vector<OrderScore> scores;
  for (int na = grid.na_min; na <= grid.na_max; ++na)
    for (int nb = grid.nb_min; nb <= grid.nb_max; ++nb)
      for (int nk = grid.nk_min; nk <= grid.nk_max; ++nk) {
        const LagOrders orders{na, nb, nk};
        check_orders(orders);
        Eigen::MatrixXd phi;
        Eigen::VectorXd target;
        regressor_matrix(data, orders, phi, target);
        // Same samples for every candidate: drop rows before the grid's largest lag.
        const std::ptrdiff_t skip = common_start - orders.max_lag();
        const std::ptrdiff_t rows = phi.rows() - skip;
        const Eigen::MatrixXd p = phi.bottomRows(rows);
        const Eigen::VectorXd t = target.tail(rows);
        const Eigen::VectorXd theta = least_squares(p, t);
        const double n = static_cast<double>(rows);
        const double d = static_cast<double>(p.cols());
        const double loss = (t - p * theta).squaredNorm() / n;
        const double score = criterion == OrderCriterion::aic
                                 ? n * std::log(std::max(loss, 1e-300)) + 2.0 * d
                                 : loss * (1.0 + d / n) / (1.0 - d / n);
        scores.push_back({orders, loss, score});
      }
  if (scores.empty()) throw InputError("ARX order grid is empty");
  std::stable_sort(scores.begin(), scores.end(),
                   [](const OrderScore& l, const OrderScore& r) { return l.score < r.score; });
  return scores;
}

}  // namespace rheomag::identify
