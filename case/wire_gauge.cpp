// Wire gauges. AWG diameters: ASTM B258 (d_n = 0.127 mm x 92^((36 - n)/39)). Metric wire is
// given by its bare diameter. Copper fill factor = N pi d^2 / 4 / A_window (bare copper); pi/4
// is square packing of bare wire touching, the most a square-packed winding can hold.

#include "case/wire_gauge.hpp"

#include <cctype>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace rheomag::cases {

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
  return awg_diameter_relaxed(gauge);
}

double awg_diameter_relaxed(double n) {
  return 0.127e-3 * std::pow(92.0, (36.0 - n) / 39.0);
}

double awg_number(double diameter) {
  return 36.0 - 39.0 * std::log(diameter / 0.127e-3) / std::log(92.0);
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

double winding_turns(double window_area, double wire_diameter, double fill) {
  if (!(fill > 0.0 && fill <= std::numbers::pi / 4.0))
    throw InputError("coil fill_factor " + std::to_string(fill) +
                     " must be in (0, pi/4 = 0.785] (copper area / winding window area)");
  if (!(window_area > 0.0 && std::isfinite(window_area)) ||
      !(wire_diameter > 0.0 && std::isfinite(wire_diameter)))
    throw InputError("coil winding window and wire diameter must be > 0");
  const double wire_area = std::numbers::pi * wire_diameter * wire_diameter / 4.0;
  // The tiny relative allowance keeps an exact fit (e.g. fill chosen from a known turn count)
  // from rounding down one turn.
  const double turns = std::floor(fill * window_area / wire_area * (1.0 + 1e-12));
  if (turns > 1e9)
    throw InputError("coil: " + std::to_string(wire_diameter * 1e3) + " mm wire at fill factor " +
                     std::to_string(fill) +
                     " gives more than 10^9 turns in the winding window; expected a wire "
                     "diameter of a real winding (is the unit right?)");
  if (turns < 1.0)
    throw InputError("coil: not one turn of " + std::to_string(wire_diameter * 1e3) +
                     " mm wire fits the winding window at fill factor " + std::to_string(fill));
  return turns;
}

}  // namespace rheomag::cases
