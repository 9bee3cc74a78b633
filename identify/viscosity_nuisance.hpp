#pragma once
// A per-recording viscosity factor as a fitted nuisance of a family fit: when no temperature is
// recorded, each recording of a family may have run at its own fluid temperature, so its viscous
// terms (the parameters that scale with the fluid's plastic viscosity) carry a factor of their own
// within stated bounds, fitted alternately with the shared parameters (issue 32 point 5).

#include <cstddef>
#include <vector>

#include "identify/greybox.hpp"
#include "lumped/phenomenological.hpp"
#include "lumped/recording.hpp"

namespace rheomag::identify {

/// Bounds and rounds of the per-recording viscosity factor.
struct ViscosityNuisance {
  double lower = 0.5;  ///< smallest factor (a fluid about 35 K warmer at 2 %/K)
  double upper = 2.0;  ///< largest factor (about 35 K colder)
  int rounds = 2;      ///< alternations: factors with the shared parameters held, then a refit
};

/// True when parameter `index` of model `kind` scales with the fluid's viscosity (the viscous,
/// post-yield, consistency and pre-yield viscous terms and their per-field parts).
bool scales_with_viscosity(lumped::PhenoKind kind, std::size_t index);

/// `fit` with every viscosity-scaled parameter multiplied by `factor`.
GreyboxFit with_viscosity_factor(const GreyboxFit& fit, double factor);

/// The factor within `bounds` whose scaled model fits `rec` best (free run at the recording's full
/// rate, Brent's search on log(factor) to about 0.1 %).
double fit_viscosity_factor(const lumped::Recording& rec, const GreyboxFit& fit,
                            const ViscosityNuisance& bounds);

/// Scales `factors` to a geometric mean of one and moves that mean into the viscosity-scaled
/// parameters of `fit` (the shared level and the factors are otherwise one degree of freedom).
void centre_viscosity_factors(std::vector<double>& factors, GreyboxFit& fit);

/// [K] Temperature above the family's mean that a factor stands for at the viscosity slope
/// rheomag states for MR fluids (lumped::kFluidViscosityTemperatureSlope): -ln(factor) / slope.
double viscosity_temperature_offset(double factor);

}  // namespace rheomag::identify
