// Coil electrical model. AWG diameters: ASTM B258 (d_n = 0.127 mm x 92^((36 - n)/39)).
// Copper: annealed, 100 % IACS = 1/58 Ohm mm^2/m = 1.7241e-8 Ohm m at 20 C, temperature
// coefficient 0.00393 /K (IEC 60028). R = rho(T) N l_turn / (pi d^2/4); J = I / (pi d^2/4);
// P = I^2 R; tau = L / R.

#include "fluid/coil.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include "mesh/error.hpp"

namespace rheomag::fluid {

namespace {

std::string lower_without_spaces(const std::string& text) {
  std::string out;
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c)))
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

/// Parses the whole of `text` as a number; false if anything is left over.
bool parse_number(const std::string& text, double& value) {
  if (text.empty()) return false;
  std::size_t used = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == text.size() && std::isfinite(value);
}

int gauge_number(const std::string& digits) {
  if (digits == "0" || digits == "1/0") return 0;
  if (digits == "00" || digits == "2/0") return -1;
  if (digits == "000" || digits == "3/0") return -2;
  if (digits == "0000" || digits == "4/0") return -3;
  double n = 0.0;
  if (!parse_number(digits, n) || n != std::floor(n)) return 1000;
  return static_cast<int>(n);
}

}  // namespace

double awg_diameter(int gauge) {
  if (gauge < -3 || gauge > 56)
    throw InputError("AWG " + std::to_string(gauge) + " is outside 0000 (-3) .. 56");
  return 0.127e-3 * std::pow(92.0, (36.0 - gauge) / 39.0);
}

double wire_diameter(const std::string& spec) {
  const std::string s = lower_without_spaces(spec);
  const std::string accepted = "expected \"AWG 24\", \"24 AWG\" or a bare diameter like \"0.5 mm\"";
  if (s.rfind("awg", 0) == 0 || (s.size() > 3 && s.substr(s.size() - 3) == "awg")) {
    const std::string digits = s.rfind("awg", 0) == 0 ? s.substr(3) : s.substr(0, s.size() - 3);
    const int gauge = gauge_number(digits);
    if (gauge == 1000) throw InputError("wire \"" + spec + "\": bad gauge; " + accepted);
    return awg_diameter(gauge);
  }
  if (s.size() > 2 && s.substr(s.size() - 2) == "mm") {
    double mm = 0.0;
    if (!parse_number(s.substr(0, s.size() - 2), mm) || !(mm > 0.0) || mm > 20.0)
      throw InputError("wire \"" + spec + "\": diameter must be a number in (0, 20] mm; " +
                       accepted);
    return mm * 1e-3;
  }
  throw InputError("wire \"" + spec + "\": " + accepted);
}

double copper_resistivity(double temperature) {
  if (!(temperature > -273.15 && temperature < 400.0))
    throw InputError("coil temperature must be in (-273.15, 400) deg C");
  return 1.7241e-8 * (1.0 + 0.00393 * (temperature - 20.0));
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

}  // namespace rheomag::fluid
