#pragma once
// Hammerstein-Wiener models (single input): y = g( B(q)/F(q) f(u) ), with piecewise-linear input
// and output nonlinearities f, g (values at fixed breakpoints, linear extrapolation) and a linear
// output-error block, all fitted jointly by Levenberg-Marquardt (Ceres) on the simulation error.
// Start: f = g = identity, the linear block from SRIV (ident_oe.hpp).

#include <vector>

#include "identify/black_box_model.hpp"

namespace rheomag::identify {

/// A piecewise-linear map through (x_i, y_i), x increasing, extrapolated with the end slopes.
struct PiecewiseLinear {
  Eigen::VectorXd x;  ///< breakpoints (strictly increasing)
  Eigen::VectorXd y;  ///< values at the breakpoints

  /// The map at v.
  double operator()(double v) const;
};

/// Structure of a Hammerstein-Wiener model.
struct HwOptions {
  int nb = 2;            ///< numerator coefficients of the linear block
  int nf = 3;            ///< poles of the linear block
  int nk = 1;            ///< input delay [samples]
  int breakpoints = 10;  ///< breakpoints of each nonlinearity
};

/// A fitted Hammerstein-Wiener model (standardised signals inside).
class HwModel : public IdentModel {
 public:
  /// Model from its blocks and the scalings of u and y.
  HwModel(HwOptions options, PiecewiseLinear input_map, Eigen::VectorXd b, Eigen::VectorXd f,
          PiecewiseLinear output_map, double u_mean, double u_scale, double y_mean, double y_scale);

  std::string name() const override;
  std::vector<NamedValue> params() const override;
  std::ptrdiff_t warmup() const override { return options_.nf + options_.nb + options_.nk; }
  /// OE structure: one-step prediction equals simulation (zero initial state).
  Eigen::VectorXd run(const IoData& data, EvalMode mode) const override;

 private:
  HwOptions options_;
  PiecewiseLinear input_map_;
  Eigen::VectorXd b_, f_;
  PiecewiseLinear output_map_;
  double u_mean_, u_scale_, y_mean_, y_scale_;
};

/// Fits a Hammerstein-Wiener model to single-input data (InputError on bad orders/short data,
/// ConvergenceError if the fit ends unstable).
HwModel fit_hw(const IoData& data, const HwOptions& options = {});

}  // namespace rheomag::identify
