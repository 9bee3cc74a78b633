#pragma once
// How an MR fluid's off-state viscosity and yield stress follow its temperature: an Arrhenius
// (Andrade) law for the viscosity, a linear derating of the yield stress.

#include "core/quantity_domain.hpp"

namespace rheomag::fluid {

struct Fluid;

/// Temperatures [deg C] a fluid model may be evaluated at: the operating range of commercial MR
/// fluids is about -40 to 150 C; beyond it the carrier boils, freezes or degrades.
inline constexpr Domain kFluidTemperature = Domain::between(-60.0, 200.0, "deg C");

/// eta(T) = eta(T0) exp(B (1/T - 1/T0)) (T in kelvin; Andrade's law, an Arrhenius law with
/// B = E/R) and tau_y(T) = tau_y(T0) (1 + c (T - T0)). B = 0 and c = 0: no dependence.
struct FluidTemperatureLaw {
  double reference = 40.0;                ///< T0 of the fluid's viscosity and yield stress [deg C]
  double activation_temperature = 0.0;    ///< B [K]; -d ln(eta)/dT = B / T^2
  double yield_stress_coefficient = 0.0;  ///< c [1/K]

  /// eta(T) / eta(T0) at `celsius` [deg C].
  double viscosity_factor(double celsius) const;
  /// tau_y(T) / tau_y(T0) at `celsius` (InputError when the derating reaches zero).
  double yield_stress_factor(double celsius) const;
  /// True when neither property depends on the temperature.
  bool constant() const { return activation_temperature == 0.0 && yield_stress_coefficient == 0.0; }
};

/// The fluid at `celsius` [deg C]: viscosity and yield stress scaled by its law (the same fluid
/// when the law is constant). InputError outside kFluidTemperature, naming the temperature.
Fluid fluid_at_temperature(const Fluid& fluid, double celsius);

}  // namespace rheomag::fluid
