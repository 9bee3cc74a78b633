#pragma once
// Continuous-time transfer functions G(s) = B(s)/A(s) estimated from sampled data as MATLAB's
// tfest does: instrumental-variable initialisation (discrete SRIV, poles mapped s = ln z / Ts),
// then Levenberg-Marquardt (Ceres) on the simulation error. Simulation is exact for a
// zero-order-hold input: the controllable-canonical state space discretised with the matrix
// exponential. Initial states are estimated by least squares (MATLAB compare's default).

#include <Eigen/Dense>
#include <vector>

#include "identify/black_box_model.hpp"

namespace rheomag::identify {

/// G(s) = (b_nz s^nz + ... + b_0) / (s^np + a_{np-1} s^{np-1} + ... + a_0), strictly proper.
struct ContinuousTf {
  Eigen::VectorXd num;  ///< b_nz .. b_0 (highest power first)
  Eigen::VectorXd den;  ///< a_{np-1} .. a_0 (monic leading 1 omitted)

  /// Number of poles.
  int poles() const { return static_cast<int>(den.size()); }
  /// Number of zeros.
  int zeros() const { return static_cast<int>(num.size()) - 1; }
  /// Poles (roots of A).
  Eigen::VectorXcd pole_values() const;
  /// True if every pole has a negative real part.
  bool stable() const;
  /// G(0) = b_0 / a_0.
  double dc_gain() const { return num(num.size() - 1) / den(den.size() - 1); }
};

/// Zero-order-hold discretisation x(k+1) = Ad x(k) + Bd u(k), y(k) = C x(k).
struct DiscreteStateSpace {
  Eigen::MatrixXd ad;
  Eigen::VectorXd bd;
  Eigen::RowVectorXd c;
};

/// ZOH discretisation of G's controllable-canonical realisation with step h [s] (expm of the
/// augmented matrix [[A, B], [0, 0]] h).
DiscreteStateSpace discretise_zoh(const ContinuousTf& g, double h);

/// Output of G driven by the ZOH input u sampled every h, from state x0 (zero if empty).
Eigen::VectorXd simulate_tf(const ContinuousTf& g, const Eigen::VectorXd& u, double h,
                            const Eigen::VectorXd& x0 = Eigen::VectorXd());

/// A fitted continuous transfer function with the data scaling used to fit it.
class TfModel : public IdentModel {
 public:
  /// Model from the transfer function in physical units (time in s).
  TfModel(ContinuousTf g, double sample_time);

  std::string name() const override;
  std::vector<NamedValue> params() const override;
  std::ptrdiff_t warmup() const override { return 0; }
  /// OE structure: one-step prediction equals simulation; the initial state is fitted to data.y.
  Eigen::VectorXd run(const IoData& data, EvalMode mode) const override;

  /// The transfer function (physical units).
  const ContinuousTf& tf() const { return g_; }

 private:
  ContinuousTf g_;
  double sample_time_;
};

/// tfest-like fit of a transfer function with np poles and nz < np zeros to single-input data.
/// Throws InputError on bad orders or too short data, ConvergenceError if no stable model is found.
TfModel fit_tf(const IoData& data, int np, int nz);

/// Fits every (np, nz) with 1 <= np <= max_poles, 0 <= nz < np and returns the lowest-AIC one.
TfModel fit_tf_auto(const IoData& data, int max_poles = 4);

}  // namespace rheomag::identify
