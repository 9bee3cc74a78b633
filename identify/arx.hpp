#pragma once
// Linear ARX models A(q) y = B(q) u + e fitted by least squares (Householder QR), and the
// AIC / FPE order selection of paper 003 (MATLAB arxstruc/selstruc) over a bounded grid.

#include <vector>

#include "identify/black_box_model.hpp"
#include "identify/regressors.hpp"

namespace rheomag::identify {

/// A fitted ARX model y(k) = -a1 y(k-1) - ... - a_na y(k-na) + sum_j sum_i b_ji u_j(k-nk-i+1).
class ArxModel : public IdentModel {
 public:
  /// Model from orders and the least-squares coefficient vector [-a; b_1; ...; b_nu].
  ArxModel(LagOrders orders, Eigen::VectorXd theta, std::ptrdiff_t inputs);

  std::string name() const override;
  std::vector<NamedValue> params() const override;
  std::ptrdiff_t warmup() const override { return orders_.max_lag(); }
  Eigen::VectorXd run(const IoData& data, EvalMode mode) const override;

  /// A-polynomial coefficients a1..a_na (MATLAB sign convention, A = 1 + a1 q^-1 + ...).
  Eigen::VectorXd a() const { return -theta_.head(orders_.na); }
  /// B-polynomial coefficients of drive j: b_1..b_nb, applied from delay nk on.
  Eigen::VectorXd b(std::ptrdiff_t j = 0) const {
    return theta_.segment(orders_.na + j * orders_.nb, orders_.nb);
  }
  /// The orders.
  const LagOrders& orders() const { return orders_; }

 private:
  LagOrders orders_;
  Eigen::VectorXd theta_;
  std::ptrdiff_t inputs_;
};

/// Least-squares ARX fit; InputError if the data are too short for the orders.
ArxModel fit_arx(const IoData& data, const LagOrders& orders);

/// Information criterion used to pick ARX orders.
enum class OrderCriterion {
  aic,  ///< Akaike: N ln V + 2 d
  fpe   ///< Akaike's final prediction error: V (1 + d/N) / (1 - d/N)
};

/// Bounds of the order grid searched by select_arx_orders (inclusive).
struct ArxGrid {
  int na_min = 1, na_max = 5;
  int nb_min = 1, nb_max = 5;
  int nk_min = 0, nk_max = 3;
};

/// One candidate of an order search: orders, loss V (mean squared one-step residual) and score.
struct OrderScore {
  LagOrders orders;
  double loss = 0.0;
  double score = 0.0;
};

/// Fits every ARX order of `grid` on the same samples (those past the grid's largest lag) and
/// returns all candidates, best (lowest criterion) first.
std::vector<OrderScore> rank_arx_orders(const IoData& data, const ArxGrid& grid,
                                        OrderCriterion criterion);

}  // namespace rheomag::identify
