#include "identify/svr.hpp"

#include <libsvm/svm.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"

namespace rheomag::identify {

/// Owns a libsvm model together with the nodes its support vectors point into.
struct SvrStorage {
  std::vector<std::vector<svm_node>> rows;
  std::vector<svm_node*> row_pointers;
  std::vector<double> targets;
  svm_problem problem{};
  svm_parameter parameter{};
  svm_model* model = nullptr;

  SvrStorage() = default;
  SvrStorage(const SvrStorage&) = delete;
  SvrStorage& operator=(const SvrStorage&) = delete;
  ~SvrStorage() {
    if (model) svm_free_and_destroy_model(&model);
  }
};

namespace {

void quiet(const char*) {}

std::vector<svm_node> to_nodes(const Eigen::VectorXd& phi) {
  std::vector<svm_node> nodes(phi.size() + 1);
  for (std::ptrdiff_t i = 0; i < phi.size(); ++i) nodes[i] = {static_cast<int>(i + 1), phi(i)};
  nodes[phi.size()] = {-1, 0.0};
  return nodes;
}

/// Trains on standardised data.
std::shared_ptr<SvrStorage> train_standardised(const IoData& scaled, const LagOrders& orders,
                                               const SvrHyper& hyper) {
  Eigen::MatrixXd phi;
  Eigen::VectorXd target;
  regressor_matrix(scaled, orders, phi, target);
  auto storage = std::make_shared<SvrStorage>();
  storage->rows.reserve(phi.rows());
  for (std::ptrdiff_t r = 0; r < phi.rows(); ++r)
    storage->rows.push_back(to_nodes(phi.row(r).transpose()));
  for (auto& row : storage->rows) storage->row_pointers.push_back(row.data());
  storage->targets.assign(target.data(), target.data() + target.size());
  storage->problem.l = static_cast<int>(phi.rows());
  storage->problem.y = storage->targets.data();
  storage->problem.x = storage->row_pointers.data();
  svm_parameter& p = storage->parameter;
  p.svm_type = EPSILON_SVR;
  p.kernel_type = RBF;
  p.gamma = hyper.gamma;
  p.C = hyper.c;
  p.p = hyper.epsilon;
  p.cache_size = 100;
  p.eps = 1e-3;
  p.shrinking = 1;
  p.probability = 0;
  p.nr_weight = 0;
  if (const char* error = svm_check_parameter(&storage->problem, &p))
    throw InputError(std::string("svr: ") + error);
  svm_set_print_string_function(&quiet);
  storage->model = svm_train(&storage->problem, &p);
  return storage;
}

Eigen::VectorXd run_standardised(const SvrStorage& storage, const IoData& scaled,
                                 const LagOrders& orders, EvalMode mode) {
  return run_regression_model(
      scaled, orders,
      [&storage](const Eigen::VectorXd& phi) {
        const std::vector<svm_node> nodes = to_nodes(phi);
        return svm_predict(storage.model, nodes.data());
      },
      mode);
}

}  // namespace

SvrModel::SvrModel(LagOrders orders, SvrHyper hyper, std::shared_ptr<const SvrStorage> storage,
                   Standardisation scaling)
    : orders_(orders), hyper_(hyper), storage_(std::move(storage)), scaling_(std::move(scaling)) {}

std::string SvrModel::name() const {
  return "svr:" + std::to_string(orders_.na) + "," + std::to_string(orders_.nb) + "," +
         std::to_string(orders_.nk);
}

std::vector<NamedValue> SvrModel::params() const {
  return {{"na", orders_.na},
          {"nb", orders_.nb},
          {"nk", orders_.nk},
          {"C", hyper_.c},
          {"gamma", hyper_.gamma},
          {"epsilon", hyper_.epsilon},
          {"support_vectors", static_cast<double>(svm_get_nr_sv(storage_->model))},
          {"y_mean", scaling_.y_mean},
          {"y_scale", scaling_.y_scale}};
}

Eigen::VectorXd SvrModel::run(const IoData& data, EvalMode mode) const {
  return scaling_.restore(run_standardised(*storage_, scaling_.apply(data, "svr"), orders_, mode));
}

SvrModel train_svr(const IoData& data, const LagOrders& orders, const SvrHyper& hyper) {
  if (orders.na < 0 || orders.nb < 1 || orders.nk < 0)
    throw InputError("svr needs na >= 0, nb >= 1, nk >= 0");
  const Standardisation scaling = Standardisation::of(data);
  const IoData scaled = scaling.apply(data, "svr");
  return SvrModel(orders, hyper, train_standardised(scaled, orders, hyper), scaling);
}

SvrModel fit_svr(const IoData& data, const SvrSearch& search) {
  const std::ptrdiff_t n = data.size();
  const std::ptrdiff_t split = (3 * n) / 4;
  int largest_lag = 0;
  for (const auto& lag : search.lags) largest_lag = std::max(largest_lag, lag.max_lag());
  if (split < 20 + largest_lag || n - split < 10 + largest_lag)
    throw InputError("too few samples (" + std::to_string(n) + ") for the svr search");
  const Standardisation scaling = Standardisation::of(data);
  const IoData scaled = scaling.apply(data, "svr");
  const IoData fit_part = slice(scaled, 0, split), check_part = slice(scaled, split, n);
  LagOrders best_lag = search.lags.front();
  SvrHyper best_hyper;
  double best_error = std::numeric_limits<double>::infinity();
  for (const auto& lag : search.lags)
    for (double c : search.c)
      for (double g : search.gamma)
        for (double e : search.epsilon) {
          const SvrHyper hyper{c, g / lag.size(data.inputs()), e};
          const auto storage = train_standardised(fit_part, lag, hyper);
          const Eigen::VectorXd sim =
              run_standardised(*storage, check_part, lag, EvalMode::simulation);
          const double error =
              (sim - check_part.y).tail(check_part.size() - largest_lag).squaredNorm();
          if (error < best_error) {
            best_error = error;
            best_lag = lag;
            best_hyper = hyper;
          }
        }
  return SvrModel(best_lag, best_hyper, train_standardised(scaled, best_lag, best_hyper), scaling);
}

}  // namespace rheomag::identify
