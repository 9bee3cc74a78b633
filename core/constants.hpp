#pragma once
// Physical constants shared by every layer (SI units).

#include <numbers>

namespace rheomag {

/// Vacuum permeability mu0 [H/m] (the pre-2019 exact value; the 2019 SI value differs by 1e-10).
inline constexpr double kMu0 = 4.0e-7 * std::numbers::pi;

/// 2 pi, one full turn [rad].
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// Vacuum reluctivity nu0 = 1/mu0 [m/H].
inline constexpr double kNu0 = 1.0 / kMu0;

}  // namespace rheomag
