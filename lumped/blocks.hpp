#pragma once
// Lumped blocks of the valve/damper chain, each a small set of named SI parameters with the
// algebraic law or state derivative it contributes to x' = f(x, u, t), y = g(x, u).

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "lumped/valve_chain_map.hpp"

namespace rheomag::lumped {

/// Copper's temperature coefficient of resistance [1/K] near 20 degC.
inline constexpr double kCopperAlpha = 0.00393;

/// Coil winding: R(T) = resistance_20c (1 + alpha (T - 20 degC)); linear inductance or a flux
/// table.
struct CoilBlock {
  double resistance_20c = 8.9;                    ///< [ohm] at 20 degC
  double temperature_coefficient = kCopperAlpha;  ///< [1/K]
  double inductance = 0.0;                        ///< [H] linear inductance; 0 = none
  std::vector<double> table_current;              ///< [A] lambda(I) table (increasing, from 0)
  std::vector<double> table_flux;                 ///< [Wb] flux linkage at table_current
  /// Resistance [ohm] at temperature T [degC].
  double resistance(double temperature_c) const {
    return resistance_20c * (1.0 + temperature_coefficient * (temperature_c - 20.0));
  }
  /// True if the coil has a flux-linkage table (nonlinear inductor).
  bool nonlinear() const { return !table_current.empty(); }
  /// Flux linkage [Wb] at current i [A] from the table (odd-symmetric, linear interpolation,
  /// extrapolated with the last slope).
  double flux_of_current(double i) const;
  /// Current [A] at flux linkage lambda [Wb], the inverse of flux_of_current.
  double current_of_flux(double lambda) const;
};

/// Coil thermal RC: C dT/dt = i^2 R(T) - (T - T_amb) / R_th, C = time_constant / R_th.
struct ThermalBlock {
  double thermal_resistance = 2.0;       ///< [K/W] coil to ambient
  double thermal_time_constant = 600.0;  ///< [s] R_th C_th
  double ambient_c = 20.0;               ///< [degC]
  /// dT/dt [K/s] for Joule power `power` [W] at temperature T [degC].
  double rate(double power, double temperature_c) const {
    const double capacitance = thermal_time_constant / thermal_resistance;
    return (power - (temperature_c - ambient_c) / thermal_resistance) / capacitance;
  }
};

/// Viscosity-temperature slope of MR fluids [1/K] near 40 degC: d ln(eta)/dT = -B / T^2 of an
/// Andrade law with B = 1960 K (the value fluid/fluid_temperature states for MRF-132DG and
/// MRC-C1L, an assumption of rheomag, docs/thermal.md) at T = 313 K.
inline constexpr double kFluidViscosityTemperatureSlope = 0.02;

/// Fluid heating in the valve or damper: the dissipated power P = dp Q (the valve's pressure drop
/// times its flow) warms the fluid, C d(theta)/dt = P - theta / R_th, and its viscosity falls,
/// eta / eta_0 = exp(-slope theta); the yield stress is left unchanged (its derating is ten
/// times weaker: fluid/fluid_temperature).
struct FluidHeatingBlock {
  double thermal_resistance = 0.5;                           ///< [K/W] fluid to ambient
  double thermal_time_constant = 600;                        ///< [s] R_th C_th
  double viscosity_slope = kFluidViscosityTemperatureSlope;  ///< [1/K] -d ln(eta)/dT
  /// d(theta)/dt [K/s] for dissipated power `power` [W] at temperature rise `rise` [K].
  double rate(double power, double rise) const {
    return (power * thermal_resistance - rise) / thermal_time_constant;
  }
  /// Viscosity over its value at the start, at temperature rise `rise` [K].
  double viscous_factor(double rise) const { return std::exp(-viscosity_slope * rise); }
};

/// Duhem magnetic hysteresis of the coil (paper 004 eqs. 2-3):
/// dlambda/dt = a |di/dt| (f(i) - lambda) + d di/dt, f(i) = b1 tanh(b2 i).
struct DuhemBlock {
  double a = 2.0;                ///< [1/A]
  double b1 = 0.05;              ///< [Wb]
  double b2 = 0.5;               ///< [1/A]
  double d = 0.01;               ///< [H]
  double flux_per_ampere = 0.0;  ///< [Wb/A] converts flux back to a field-equivalent current
  /// dlambda/di along the current direction sign(di/dt) = direction (smooth, in [-1, 1]).
  double incremental_inductance(double i, double lambda, double direction) const;
};

/// First-order lag tau y' = u - y (eddy-current flux lag, MR fluid response time).
struct LagBlock {
  double time_constant = 0.0;  ///< [s]; 0 = no lag
  /// y' for input u and state y.
  double rate(double input, double state) const { return (input - state) / time_constant; }
};

/// Eddy-current time constant of a solid cylindrical core [s]: the slowest diffusion mode,
/// tau = mu0 mu_r sigma r^2 / j01^2 (j01 = 2.405, first zero of J0).
double eddy_time_constant(double relative_permeability, double conductivity, double radius);

/// Coil current driver: voltage mode (V = gain * command) or current mode with PI control and a
/// voltage limit (smooth saturation V_max tanh(V_pi / V_max); back-calculation anti-windup beyond
/// the limit).
struct DriverBlock {
  double gain = 1.0;            ///< [V/V] voltage mode: coil voltage per command volt
  double kp = 50.0;             ///< [V/A] current mode proportional gain
  double ki = 5000.0;           ///< [V/(A s)] current mode integral gain
  double voltage_limit = 24.0;  ///< [V] supply limit
  /// Saturated coil voltage [V] from the PI output.
  double saturate(double v) const;
};

/// Bingham valve static map: dp = scale p_y(|i|) sign(Q) + R Q, sign regularised by
/// tanh(Q / regularisation_flow); p_y from a yield-pressure table (as the sidecar's [valve]).
/// With `chain` set, the map is the fluid chain's table of an FE case instead (yield part times
/// yield_scale, viscous part times viscous_scale; the yield table and R are then unused).
struct ValveMapBlock {
  std::vector<double> yield_current;   ///< [A]
  std::vector<double> yield_pressure;  ///< [Pa]
  double viscous_resistance = 1.5e10;  ///< [Pa s/m^3]
  double yield_scale = 1.0;            ///< [-] calibration factor on the table
  double regularisation_flow = 1e-8;   ///< [m^3/s] width of the smooth sign
  /// [-] shape of the table map's knee: 0 the Bingham line; 1 the exact slit (Buckingham) law with
  /// the line as its asymptote (yield part p_y (1 - delta^2 / 3), lumped/slit_law.hpp); between,
  /// yield part p_y (1 - slit_fraction delta^2 / 3). Unused by a chain map.
  double slit_fraction = 0.0;
  std::string case_file;                       ///< FE case of the valve (chain map), or empty
  double viscous_scale = 1.0;                  ///< [-] chain map: factor on the viscous part
  std::shared_ptr<const ChainMapTable> chain;  ///< chain map tabulated from case_file
  /// Yield pressure [Pa] at current i [A] (linear interpolation, clamped).
  double yield(double current) const;
  /// Pressure drop [Pa] at flow Q [m^3/s] and current i [A], the viscous part times
  /// `viscous_factor` (a warmer, thinner fluid: FluidHeatingBlock).
  double pressure_drop(double flow, double current, double viscous_factor = 1.0) const;
  /// Flow [m^3/s] at pressure drop dp [Pa]: the smooth inverse ramp(dp - p_y) - ramp(-dp - p_y),
  /// ramp width R * regularisation_flow (the plug switch regularised); viscous part as above.
  double flow(double pressure_drop, double current, double viscous_factor = 1.0) const;
};

/// Chambers of a rig's hydraulic loop, one either side of the valve, each a ChamberBlock.
constexpr double kRigChambers = 2.0;

/// Chamber compliance: oil volume with bulk modulus plus entrained air (isothermal or adiabatic).
struct ChamberBlock {
  double oil_volume = 2e-5;     ///< [m^3] per chamber
  double bulk_modulus = 1.5e9;  ///< [Pa]
  double air_volume = 0.0;      ///< [m^3] per chamber at the precharge pressure
  double precharge = 1e5;       ///< [Pa] absolute pressure at rest
  double polytropic = 1.0;      ///< 1 = isothermal, 1.4 = adiabatic
  /// Hydraulic capacitance dV/dp [m^3/Pa] at absolute pressure p > 0 [Pa].
  double capacitance(double pressure) const;
  /// Fluid volume [m^3] pushed into the chamber to raise it from the precharge to absolute
  /// pressure p > 0: oil compression plus air compression (negative below the precharge; the
  /// air expands without bound as p -> 0, so no absolute pressure below zero is reached).
  double stored_volume(double pressure) const;
  /// Absolute pressure [Pa] at stored volume `volume` [m^3]: the inverse of stored_volume.
  double pressure_at(double volume) const;
};

}  // namespace rheomag::lumped
