#pragma once
// Quantities written with a unit on the command line ("1.5L/min", "10mm", "500mA"): one unit
// table per kind of quantity, SI when no unit is written.

#include <string>
#include <string_view>
#include <vector>

namespace rheomag {

/// What a command-line quantity measures; each kind has its SI unit and the units it accepts.
enum class QuantityKind {
  length,         ///< m
  current,        ///< A
  voltage,        ///< V
  flow,           ///< m^3/s
  velocity,       ///< m/s
  angular_speed,  ///< rad/s
  time,           ///< s
  pressure,       ///< Pa
};

/// The SI unit of a kind, as printed after its values ("m^3/s").
std::string_view si_unit(QuantityKind kind);

/// The units a kind accepts, comma-separated for messages and --help ("m, cm, mm, um, in").
std::string accepted_units(QuantityKind kind);

/// A number with an optional unit of `kind` ("1.5L/min", "1.5 L/min", "2e-5"), in SI. InputError
/// "<option>: ..." naming the value, the unit and the units accepted when it does not read.
double parse_quantity(std::string_view text, QuantityKind kind, std::string_view option);

/// Each of `texts` read by parse_quantity (the comma-separated values of a list option).
std::vector<double> parse_quantities(const std::vector<std::string>& texts, QuantityKind kind,
                                     std::string_view option);

}  // namespace rheomag
