#pragma once
// Continuous-time transfer functions simulated in state space, and paper 000's TF14 (Table 7).

#include <vector>

namespace rheomag::lumped {

/// G(s) = num(s) / den(s), coefficients in descending powers of s; deg num < deg den.
struct TransferFunction {
  std::vector<double> num;
  std::vector<double> den;
};

/// TF14 of paper 000 (eq. 7, Table 7): coil current [A] -> pressure drop [bar], 13 zeros-side and
/// 15 poles-side coefficients (29 in total).
TransferFunction tf14_paper000();

/// Steady-state gain num(0) / den(0).
double dc_gain(const TransferFunction& tf);

/// Free-run response to u sampled at t (u piecewise linear), zero initial state, integrated in
/// controllable canonical form with rosenbrock4. Throws InputError for malformed coefficients.
std::vector<double> simulate_transfer_function(const TransferFunction& tf,
                                               const std::vector<double>& t,
                                               const std::vector<double>& u);

}  // namespace rheomag::lumped
