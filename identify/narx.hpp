#pragma once
// Polynomial NARX models: y(k) = sum of selected monomials (degree <= d) of the lagged
// regressors y(k-1..k-na), u(k-nk..), plus a constant. Terms are chosen by forward orthogonal
// least squares (FROLS, error-reduction ratio; Billings 2013) and their number by the
// free-run error on the last quarter of the training data.

#include <vector>

#include "identify/black_box_model.hpp"
#include "identify/regressors.hpp"

namespace rheomag::identify {

/// A monomial of regressor entries: indices into the regressor vector (repeats = powers).
using Monomial = std::vector<int>;

/// Structure options of a polynomial NARX model.
struct NarxOptions {
  LagOrders orders{2, 4, 1};  ///< lags
  int degree = 3;             ///< largest total degree of a monomial
  int max_terms = 30;         ///< most monomials FROLS may select
};

/// A fitted polynomial NARX model (works on standardised signals internally).
class NarxModel : public IdentModel {
 public:
  /// Model from its structure, selected monomials with coefficients, and signal scalings.
  NarxModel(NarxOptions options, std::vector<Monomial> terms, Eigen::VectorXd coefficients,
            Standardisation scaling);

  std::string name() const override;
  std::vector<NamedValue> params() const override;
  std::ptrdiff_t warmup() const override { return options_.orders.max_lag(); }
  Eigen::VectorXd run(const IoData& data, EvalMode mode) const override;

  /// Number of selected monomials.
  std::size_t term_count() const { return terms_.size(); }

 private:
  NarxOptions options_;
  std::vector<Monomial> terms_;
  Eigen::VectorXd coefficients_;
  Standardisation scaling_;
};

/// All monomials of `variables` regressor entries with total degree 0..degree.
std::vector<Monomial> all_monomials(int variables, int degree);

/// Greedy FROLS order of the candidate columns of p for target y (most explanatory first),
/// at most max_terms long.
std::vector<int> frols_order(const Eigen::MatrixXd& p, const Eigen::VectorXd& y, int max_terms);

/// Fits a polynomial NARX model to data (InputError if too short for the structure).
NarxModel fit_narx(const IoData& data, const NarxOptions& options);

/// Picks the lags among `candidates` by free-run error on the last quarter of `data` (each fitted
/// on the first three quarters), then refits the winner on all of `data`.
NarxModel fit_narx_lag_search(const IoData& data, const std::vector<LagOrders>& candidates,
                              int degree = 3);

}  // namespace rheomag::identify
