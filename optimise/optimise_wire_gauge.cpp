#include "optimise/optimise_wire_gauge.hpp"

#include <cmath>
#include <cstdio>

#include "magnetostatics/wire_gauge.hpp"
#include "mesh/error.hpp"

namespace rheomag::optimise {

double awg_diameter_relaxed(double n) {
  return 0.127e-3 * std::pow(92.0, (36.0 - n) / 39.0);
}

double awg_number(double diameter) {
  return 36.0 - 39.0 * std::log(diameter / 0.127e-3) / std::log(92.0);
}

std::string wire_text(double n) {
  const double whole = std::round(n);
  if (std::abs(n - whole) < 1e-9) {
    if (whole >= 1.0) return "AWG " + std::to_string(static_cast<int>(whole));
    return "AWG " + std::string(static_cast<std::size_t>(1.0 - whole), '0');
  }
  char text[48];
  std::snprintf(text, sizeof text, "%.9g mm", awg_diameter_relaxed(n) * 1e3);
  return text;
}

double wire_gauge_start(const toml::table& table, const std::string& where) {
  const auto wire = table["geometry"]["wire"].value<std::string>();
  if (!wire || !table["geometry"]["fill_factor"])
    throw InputError(where +
                     ": \"wire_gauge\" as a design variable needs the coil wound from its wire: "
                     "[geometry] wire = \"AWG 24\" and fill_factor = 0.55 instead of turns "
                     "(docs/case-format.md)");
  const double n = awg_number(magnetostatics::wire_diameter(*wire));
  return std::abs(n - std::round(n)) < 1e-6 ? std::round(n) : n;
}

}  // namespace rheomag::optimise
