#pragma once
// Electrical side of a valve coil: wire gauge (magnetostatics/wire_gauge.hpp), resistance at
// temperature, copper fill, current density, power I^2 R and time constant L/R.

#include <string>

#include "case/wire_gauge.hpp"
#include "core/quantity_domain.hpp"

namespace rheomag::valve {

/// The wire-gauge table lives in the case layer (the case needs it for turns before the solve).
using cases::awg_diameter;
using cases::wire_diameter;

/// Temperatures [deg C] at which the linear copper model below holds: from -200 C (the line meets
/// zero resistance at -234.5 C; measured copper is within about 10 % of it down to -200 C) to
/// 250 C (above the thermal class of enamelled magnet wire, 220 C). Outside it the model is not
/// copper: -250 C gave R = -0.291 Ohm.
inline constexpr Domain kCoilTemperature = Domain::between(-200.0, 250.0, "deg C");

/// Temperature coefficient of annealed copper's resistivity at 20 C [1/K] (IEC 60028).
inline constexpr double kCopperTemperatureCoefficient = 0.00393;

/// Resistivity of annealed copper [Ohm m] at `temperature` [deg C]: 1.7241e-8 (100 % IACS at
/// 20 C) x (1 + 0.00393 (T - 20)). Throws InputError outside kCoilTemperature.
double copper_resistivity(double temperature);

/// What is known about a coil before the field solve.
struct CoilSpec {
  double turns = 0.0;             ///< number of turns
  double wire_diameter = 0.0;     ///< bare copper diameter [m]
  double mean_turn_length = 0.0;  ///< 2 pi x mean winding radius [m]
  double window_area = 0.0;       ///< winding cross-section (meridian plane) [m^2]
  double temperature = 20.0;      ///< winding temperature [deg C]
};

/// Coil quantities at one current.
struct CoilProperties {
  double turns = 0.0;
  double wire_length = 0.0;      ///< [m]
  double resistance = 0.0;       ///< at CoilSpec::temperature [Ohm]
  double copper_fill = 0.0;      ///< copper area / window area
  double current_density = 0.0;  ///< in the copper [A/m^2]
  double power = 0.0;            ///< I^2 R [W]
  double inductance = 0.0;       ///< the given (e.g. FE secant) inductance [H]
  double time_constant = 0.0;    ///< L / R [s]
};

/// Coil quantities at `current` [A] with inductance `inductance` [H] (from the field solve).
/// Throws InputError for non-positive turns, diameter, turn length or window area, or a copper
/// fill above the pi/4 of perfect square packing of bare wire.
CoilProperties coil_properties(const CoilSpec& spec, double current, double inductance);

}  // namespace rheomag::valve
