#pragma once
// SVR-NARX (paper 002): libsvm epsilon-SVR with an RBF kernel on the lagged regressors
// y(k-1..k-na), u(k-nk..k-nk-nb+1) of standardised signals, with a bounded search over lags and
// (C, gamma, epsilon) judged by free-run error on the last quarter of the training data.

#include <memory>
#include <vector>

#include "identify/black_box_model.hpp"
#include "identify/regressors.hpp"

namespace rheomag::identify {

/// Hyperparameters of one SVR: box constraint C, RBF gamma (on standardised regressors), tube
/// half-width epsilon (in output standard deviations).
struct SvrHyper {
  double c = 10.0;
  double gamma = 0.5;
  double epsilon = 0.05;
};

/// The bounded search grid of fit_svr.
struct SvrSearch {
  std::vector<LagOrders> lags{{1, 2, 1}, {2, 2, 1}, {2, 4, 1}};
  std::vector<double> c{1.0, 10.0, 100.0};
  std::vector<double> gamma{0.2, 1.0};  ///< multiplied by 1 / (regressor length)
  std::vector<double> epsilon{0.02, 0.1};
};

struct SvrStorage;  // libsvm model and the training vectors it points into

/// A fitted SVR-NARX model.
class SvrModel : public IdentModel {
 public:
  /// Wraps a trained libsvm model (see fit_svr).
  SvrModel(LagOrders orders, SvrHyper hyper, std::shared_ptr<const SvrStorage> storage,
           Standardisation scaling);

  std::string name() const override;
  std::vector<NamedValue> params() const override;
  std::ptrdiff_t warmup() const override { return orders_.max_lag(); }
  Eigen::VectorXd run(const IoData& data, EvalMode mode) const override;

 private:
  LagOrders orders_;
  SvrHyper hyper_;
  std::shared_ptr<const SvrStorage> storage_;
  Standardisation scaling_;
};

/// Trains one SVR-NARX with fixed lags and hyperparameters.
SvrModel train_svr(const IoData& data, const LagOrders& orders, const SvrHyper& hyper);

/// Searches `search` (train on the first 3/4, free-run score on the last 1/4), then retrains the
/// best on all of `data`.
SvrModel fit_svr(const IoData& data, const SvrSearch& search = {});

}  // namespace rheomag::identify
