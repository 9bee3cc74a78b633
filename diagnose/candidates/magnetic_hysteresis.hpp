#pragma once
// The Duhem block of the magnetic_hysteresis candidate (also used to build test recordings).

#include "lumped/blocks.hpp"

namespace rheomag::diagnose {

/// b2 [1/A] of the diagnosis's Duhem candidate: small, so f(i) = tanh(b2 i) / b2 is the current
/// itself and the saturation stays in the calibrated valve map.
inline constexpr double kDuhemFieldB2 = 0.01;

/// The Duhem block of the magnetic_hysteresis candidate: field-equivalent current h with
/// dh/dt = a |di/dt| (i - h) + d di/dt (paper 004 eqs. 2-3 with b1 b2 = 1, b2 -> 0).
lumped::DuhemBlock duhem_field(double a, double d);

}  // namespace rheomag::diagnose
