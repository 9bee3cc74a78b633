#include "design/quantities.hpp"

namespace rheomag::design {

std::string_view quantity_unit(Quantity q) {
  switch (q) {
    case Quantity::dp_on:
    case Quantity::dp_off:
      return "Pa";
    case Quantity::b_gap:
    case Quantity::peak_steel_b:
      return "T";
    case Quantity::inductance:
      return "H";
    case Quantity::resistance:
      return "Ohm";
    case Quantity::time_constant:
    case Quantity::rise_time:
    case Quantity::response_time:
      return "s";
    case Quantity::power:
      return "W";
    case Quantity::current_density:
      return "A/m^2";
    case Quantity::outer_radius:
    case Quantity::length:
    case Quantity::min_gap:
    case Quantity::min_wall:
      return "m";
    case Quantity::temperature_rise:
      return "K";
    case Quantity::coil_temperature:
    case Quantity::fluid_temperature:
      return "deg C";
    case Quantity::force_on:
    case Quantity::force_off:
      return "N";
    case Quantity::torque_on:
    case Quantity::torque_off:
      return "N m";
    case Quantity::mass:
      return "kg";
    case Quantity::torque_per_mass:
      return "N m/kg";
    case Quantity::dynamic_range:
    case Quantity::force_range:
    case Quantity::copper_fill:
      return "-";
  }
  return "-";
}

const std::vector<Quantity>& all_quantities() {
  static const std::vector<Quantity> list = [] {
    std::vector<Quantity> out;
    for (const auto& [q, name] : kQuantityNames.entries) out.push_back(q);
    return out;
  }();
  return list;
}

}  // namespace rheomag::design
