#pragma once
// The time-harmonic (small-signal) limit of the transient equations: at angular frequency
// omega about a steady state, (K_t + j omega (M + K_kappa)) A = F i, lambda = F . A.

#include <complex>

#include "magnetostatics/solver.hpp"
#include "transient/eddy.hpp"

namespace rheomag::transient {

/// The first circuit's response to a sinusoidal current of 1 A (complex amplitude) at one
/// frequency, about the steady state at a bias current.
struct HarmonicResponse {
  double frequency = 0.0;             ///< [Hz]
  std::complex<double> flux_linkage;  ///< lambda per ampere (the inductance L(omega)) [H]
  std::complex<double> impedance;     ///< j omega lambda per ampere (no coil resistance) [Ohm]
  double eddy_loss = 0.0;             ///< mean eddy-current power at 1 A amplitude [W]
};

/// Solves (K_t(A_bias) + j omega (M + K_kappa)) A = F on the static solver's assembly (K_t the
/// static tangent at the steady state of `bias_current` on the first circuit, the others at their
/// case currents; M and K_kappa the eddy matrices of the transient solver) with Eigen's sparse
/// LU. Exact for linear materials; for B-H curves, the incremental (small-signal) response.
/// InputError for a frequency < 0 or not finite, or a problem without circuit.
HarmonicResponse harmonic_response(magnetostatics::MagnetostaticSolver& statics,
                                   const EddyCoefficients& eddy, double frequency,
                                   double bias_current = 0.0);

}  // namespace rheomag::transient
