#pragma once
// Paper 001's LuGre-based MR valve model as a ready model: eqs. 8-9 with the current-dependent
// parameter polynomials of its Table 3, in the units the table was fitted in (Q in ml/s, dp in
// bar, z in ml, a0 in 1/ml; worked out in docs/dynamics.md), wrapped to SI.

#include <vector>

namespace rheomag::lumped {

/// Table 3 of paper 001 at coil current i [A] (clamped to the fitted range 0..1 A).
struct LuGrePaper001Params {
  double A = 0.0;      ///< [bar] stiffness term, multiplies z
  double B = 0.0;      ///< [bar] second z term (eq. 8 as printed: dp = A z + B z + C Q^alpha)
  double C = 0.0;      ///< [bar / (ml/s)^alpha] viscous term
  double alpha = 1.0;  ///< [-] exponent of the flow
  double a0 = 1.0;     ///< [1/ml] rate of the evolutionary variable
};

/// Table 3's polynomials evaluated at current i [A].
LuGrePaper001Params lugre_paper001_params(double current);

/// Pressure drop [Pa] of eqs. 8-9 at sample times t [s] for valve flow [m^3/s] and current [A]
/// (z starts at 0; |Q| and sgn(Q)|Q|^alpha regularised with width 1e-3 ml/s; rosenbrock4).
std::vector<double> simulate_lugre_paper001(const std::vector<double>& t,
                                            const std::vector<double>& flow,
                                            const std::vector<double>& current);

}  // namespace rheomag::lumped
