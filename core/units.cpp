// The unit tables of the command-line quantities.

#include "core/units.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <utility>

#include "core/error.hpp"

namespace rheomag {

namespace {

/// One accepted unit: its spelling and the SI value of one of it.
struct Unit {
  std::string_view name;
  double si;
};

/// The units of each kind, the SI unit first (the one printed back).
std::vector<Unit> units_of(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::length:
      return {{"m", 1.0}, {"cm", 1e-2}, {"mm", 1e-3}, {"um", 1e-6}, {"in", 0.0254}};
    case QuantityKind::current:
      return {{"A", 1.0}, {"mA", 1e-3}};
    case QuantityKind::voltage:
      return {{"V", 1.0}, {"mV", 1e-3}};
    case QuantityKind::flow:
      return {{"m^3/s", 1.0}, {"m3/s", 1.0},         {"L/s", 1e-3},    {"L/min", 1e-3 / 60},
              {"mL/s", 1e-6}, {"mL/min", 1e-6 / 60}, {"cm^3/s", 1e-6}, {"cm3/s", 1e-6}};
    case QuantityKind::velocity:
      return {{"m/s", 1.0}, {"cm/s", 1e-2}, {"mm/s", 1e-3}};
    case QuantityKind::angular_speed:
      return {
          {"rad/s", 1.0}, {"rpm", 2.0 * std::numbers::pi / 60.0}, {"Hz", 2.0 * std::numbers::pi}};
    case QuantityKind::time:
      return {{"s", 1.0}, {"ms", 1e-3}, {"us", 1e-6}, {"min", 60.0}};
    case QuantityKind::pressure:
      return {{"Pa", 1.0}, {"kPa", 1e3}, {"MPa", 1e6}, {"bar", 1e5}};
  }
  return {};
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

}  // namespace

std::string_view si_unit(QuantityKind kind) {
  return units_of(kind).front().name;
}

std::string accepted_units(QuantityKind kind) {
  std::string list;
  for (const Unit& u : units_of(kind)) list += (list.empty() ? "" : ", ") + std::string(u.name);
  return list;
}

double parse_quantity(std::string_view text, QuantityKind kind, std::string_view option) {
  const std::string value(trim(text));
  const std::string where(option);
  char* end = nullptr;
  const double number = std::strtod(value.c_str(), &end);
  if (end == value.c_str() || !std::isfinite(number))
    throw InputError(where + ": expected a number with an optional unit (" + accepted_units(kind) +
                     "; " + std::string(si_unit(kind)) + " when none), got \"" + value + "\"");
  const std::string_view unit = trim(std::string_view(end));
  if (unit.empty()) return number;
  // Litres are also written with a lower-case l ("1.5l/min").
  std::string spelled(unit);
  if (!spelled.empty() && spelled.front() == 'l' && kind == QuantityKind::flow) spelled[0] = 'L';
  if (spelled.size() > 1 && spelled[0] == 'm' && spelled[1] == 'l' && kind == QuantityKind::flow)
    spelled[1] = 'L';
  for (const Unit& u : units_of(kind))
    if (u.name == spelled) return number * u.si;
  throw InputError(where + ": unknown unit \"" + std::string(unit) + "\" in \"" + value +
                   "\"; accepted: " + accepted_units(kind) + " (" + std::string(si_unit(kind)) +
                   " when none is written)");
}

std::vector<double> parse_quantities(const std::vector<std::string>& texts, QuantityKind kind,
                                     std::string_view option) {
  std::vector<double> values;
  values.reserve(texts.size());
  for (const std::string& t : texts) values.push_back(parse_quantity(t, kind, option));
  return values;
}

}  // namespace rheomag
