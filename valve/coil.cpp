// Coil electrical model (wire gauges: magnetostatics/wire_gauge.cpp).
// Copper: annealed, 100 % IACS = 1/58 Ohm mm^2/m = 1.7241e-8 Ohm m at 20 C, temperature
// coefficient 0.00393 /K (IEC 60028). R = rho(T) N l_turn / (pi d^2/4); J = I / (pi d^2/4);
// P = I^2 R; tau = L / R.

#include "valve/coil.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/error.hpp"

namespace rheomag::valve {

double copper_resistivity(double temperature) {
  const std::string why = kCoilTemperature.violation(temperature);
  if (!why.empty())
    throw InputError("coil temperature: " + why +
                     " (where the linear resistivity of copper holds)");
  const double rho = 1.7241e-8 * (1.0 + kCopperTemperatureCoefficient * (temperature - 20.0));
  if (!(rho > 0.0)) throw std::logic_error("copper resistivity <= 0 inside its domain");
  return rho;
}

CoilProperties coil_properties(const CoilSpec& spec, double current, double inductance) {
  if (!(spec.turns > 0.0) || !(spec.wire_diameter > 0.0) || !(spec.mean_turn_length > 0.0) ||
      !(spec.window_area > 0.0))
    throw InputError("coil needs turns, wire diameter, mean turn length and window area > 0");
  if (!std::isfinite(current) || !std::isfinite(inductance) || inductance < 0.0)
    throw InputError("coil current must be finite and inductance finite and >= 0");
  const double wire_area = std::numbers::pi * spec.wire_diameter * spec.wire_diameter / 4.0;
  CoilProperties out;
  out.turns = spec.turns;
  out.copper_fill = spec.turns * wire_area / spec.window_area;
  if (out.copper_fill > std::numbers::pi / 4.0)
    throw InputError("coil: " + std::to_string(spec.turns) + " turns of " +
                     std::to_string(spec.wire_diameter * 1e3) +
                     " mm wire do not fit the winding window (copper fill " +
                     std::to_string(out.copper_fill) + " > pi/4)");
  out.wire_length = spec.turns * spec.mean_turn_length;
  out.resistance = copper_resistivity(spec.temperature) * out.wire_length / wire_area;
  out.current_density = std::abs(current) / wire_area;
  out.power = current * current * out.resistance;
  out.inductance = inductance;
  out.time_constant = inductance / out.resistance;
  return out;
}

}  // namespace rheomag::valve
