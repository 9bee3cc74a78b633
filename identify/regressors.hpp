#pragma once
// Lagged regressors of ARX-type models: past outputs y(k-1..k-na) and, for each drive j,
// u_j(k-nk .. k-nk-nb+1); and the loop that runs such a model in simulation or prediction.

#include <Eigen/Dense>
#include <functional>
#include <string>

#include "identify/black_box_model.hpp"
#include "identify/io_data.hpp"

namespace rheomag::identify {

/// Orders of an ARX-type regressor: na past outputs, nb past inputs per drive, input delay nk.
struct LagOrders {
  int na = 2;  ///< number of past outputs
  int nb = 2;  ///< number of input samples per drive
  int nk = 1;  ///< input delay [samples]

  /// First sample index whose regressor is fully defined by the data.
  int max_lag() const { return std::max(na, nb + nk - 1); }
  /// Regressor length for `inputs` drives.
  int size(std::ptrdiff_t inputs) const { return na + nb * static_cast<int>(inputs); }
};

/// Centring and scaling of each signal that regression models (narx, svr) work in: mean and rms
/// spread of every drive and of the output (spread 1 for a constant signal).
struct Standardisation {
  Eigen::VectorXd u_mean, u_scale;
  double y_mean = 0.0, y_scale = 1.0;
  /// The means and spreads of `data`.
  static Standardisation of(const IoData& data);
  /// `data` centred and scaled; InputError naming `model` if its number of drives differs.
  IoData apply(const IoData& data, const std::string& model) const;
  /// A standardised output back in the data's units.
  Eigen::VectorXd restore(const Eigen::VectorXd& y) const {
    return (y.array() * y_scale + y_mean).matrix();
  }
};

/// Fills phi with the regressor at sample k, past outputs taken from `y_history`.
void fill_regressor(const Eigen::VectorXd& y_history, const Eigen::MatrixXd& u, std::ptrdiff_t k,
                    const LagOrders& orders, Eigen::Ref<Eigen::VectorXd> phi);

/// Regressor matrix (rows k = max_lag .. N-1) from measured data, and matching targets.
void regressor_matrix(const IoData& data, const LagOrders& orders, Eigen::MatrixXd& phi,
                      Eigen::VectorXd& target);

/// Runs y(k) = f(phi(k)) over `data`: the first max_lag samples are the measured ones; in
/// simulation mode phi uses past model outputs, in prediction mode past measured outputs.
/// A run whose output leaves 1e3 x the measured range is held there (unstable free run).
Eigen::VectorXd run_regression_model(const IoData& data, const LagOrders& orders,
                                     const std::function<double(const Eigen::VectorXd&)>& f,
                                     EvalMode mode);

}  // namespace rheomag::identify
