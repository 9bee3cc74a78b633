#pragma once
// The quantities a design is evaluated for: usable as the optimiser's objective, in its
// constraints and on a Pareto front, each with its SI unit.

#include <array>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "core/enum_names.hpp"

namespace rheomag::design {

/// One computed quantity of a design.
enum class Quantity {
  dp_on,             ///< pressure drop at the on-state current and design flow [Pa]
  dp_off,            ///< pressure drop at zero field [Pa]
  dynamic_range,     ///< dp_on / dp_off [-]
  b_gap,             ///< mean |B| over the gaps [T]
  peak_steel_b,      ///< largest element |B| in nonlinear (steel) materials [T]
  inductance,        ///< secant inductance of the coil at the on-state current [H]
  resistance,        ///< coil resistance [Ohm]
  time_constant,     ///< L / R [s]
  power,             ///< I^2 R [W]
  current_density,   ///< in the copper [A/m^2]
  copper_fill,       ///< copper area / window area [-]
  outer_radius,      ///< of the geometry [m]
  length,            ///< axial extent of the geometry [m]
  min_gap,           ///< smallest gap clearance [m]
  min_wall,          ///< thinnest steel wall of the template [m]
  temperature_rise,  ///< steady coil temperature rise [K]
  rise_time,         ///< 90 % rise time of the coil current after a voltage step [s]
  force_on,          ///< damper force at the on-state current and design velocity [N]
  force_off,         ///< damper force at zero field, same velocity [N]
  force_range,       ///< (force_on - gas force) / (force_off - gas force) [-]
  torque_on,         ///< brake torque at the on-state current and design speed [N m]
  torque_off,        ///< brake torque at zero field, same speed [N m]
  mass,              ///< mass of the case's regions (axisymmetric volumes x densities) [kg]
  torque_per_mass,   ///< torque_on / mass [N m/kg]
  /// t90 of the slowest gap's mean |B| after a voltage step on and off, eddy currents included
  /// (transient magnetics): the slower of the two [s]
  response_time,
  coil_temperature,   ///< steady mean winding temperature, FE heat conduction (thermal/) [deg C]
  fluid_temperature,  ///< steady largest temperature in the fluid gaps, likewise [deg C]
};

/// Number of quantities.
inline constexpr std::size_t kQuantityCount = 27;

/// The quantities' names as written in case files and outputs.
inline constexpr auto kQuantityNames = enum_names<Quantity>({
    {Quantity::dp_on, "dp_on"},
    {Quantity::dp_off, "dp_off"},
    {Quantity::dynamic_range, "dynamic_range"},
    {Quantity::b_gap, "b_gap"},
    {Quantity::peak_steel_b, "peak_steel_b"},
    {Quantity::inductance, "inductance"},
    {Quantity::resistance, "resistance"},
    {Quantity::time_constant, "time_constant"},
    {Quantity::power, "power"},
    {Quantity::current_density, "current_density"},
    {Quantity::copper_fill, "copper_fill"},
    {Quantity::outer_radius, "outer_radius"},
    {Quantity::length, "length"},
    {Quantity::min_gap, "min_gap"},
    {Quantity::min_wall, "min_wall"},
    {Quantity::temperature_rise, "temperature_rise"},
    {Quantity::rise_time, "rise_time"},
    {Quantity::force_on, "force_on"},
    {Quantity::force_off, "force_off"},
    {Quantity::force_range, "force_range"},
    {Quantity::torque_on, "torque_on"},
    {Quantity::torque_off, "torque_off"},
    {Quantity::mass, "mass"},
    {Quantity::torque_per_mass, "torque_per_mass"},
    {Quantity::response_time, "response_time"},
    {Quantity::coil_temperature, "coil_temperature"},
    {Quantity::fluid_temperature, "fluid_temperature"},
});

/// The quantities of a valve at the design flow ([optimise] flow).
inline constexpr std::array kValveQuantities = {Quantity::dp_on, Quantity::dp_off,
                                                Quantity::dynamic_range};
/// The quantities of a damper at the design velocity ([optimise] velocity, a [damper] case).
inline constexpr std::array kDamperQuantities = {Quantity::force_on, Quantity::force_off,
                                                 Quantity::force_range};
/// The quantities of a brake at the design speed ([optimise] speed).
inline constexpr std::array kBrakeQuantities = {Quantity::torque_on, Quantity::torque_off,
                                                Quantity::torque_per_mass};

/// The name of a quantity.
inline std::string quantity_name(Quantity q) {
  return std::string(kQuantityNames.name(q));
}

/// The SI unit of a quantity ("-" for ratios).
std::string_view quantity_unit(Quantity q);

/// Every quantity, in output order.
const std::vector<Quantity>& all_quantities();

/// The quantities of one design; a quantity the case cannot give (no wire, no template) is NaN.
class Quantities {
 public:
  Quantities() { values_.fill(NAN); }
  double& operator[](Quantity q) { return values_[static_cast<std::size_t>(q)]; }
  double operator[](Quantity q) const { return values_[static_cast<std::size_t>(q)]; }
  /// True when the design gives a finite value.
  bool has(Quantity q) const { return std::isfinite((*this)[q]); }

 private:
  std::array<double, kQuantityCount> values_;
};

}  // namespace rheomag::design
