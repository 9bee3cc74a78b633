#pragma once
// What the heat-conduction solver needs besides the mesh: each region's conductivity, heat
// capacity and heat source, and the condition on each outer surface of the thermal model.

#include <string>
#include <vector>

#include "core/enum_names.hpp"

namespace rheomag::thermal {

/// One region of the thermal model (index as Problem::regions).
struct HeatRegion {
  bool active = false;         ///< part of the thermal model (false: surroundings, e.g. air)
  double conductivity = 0.0;   ///< k [W/(m K)]
  double heat_capacity = 0.0;  ///< rho c_p [J/(m^3 K)]
  double source = 0.0;         ///< heat generated, uniform over the region [W/m^3]
  /// Heat exchanged with a fluid flowing through the region, beta (T - T_in) [W/m^3] per K:
  /// a valve's through-flow carries beta (T - exchange_temperature) away (0: none).
  double exchange = 0.0;
  double exchange_temperature = 0.0;  ///< T_in of the exchange [deg C]
};

/// What holds on an outer surface of the thermal model.
enum class SurfaceKind {
  convection,         ///< -k dT/dn = h (T - T_ambient)
  fixed_temperature,  ///< T = temperature
  insulated,          ///< no heat flow (also the symmetry condition)
};

/// The surface kinds' names in inputs and outputs.
inline constexpr auto kSurfaceKindNames = enum_names<SurfaceKind>({
    {SurfaceKind::convection, "convection"},
    {SurfaceKind::fixed_temperature, "temperature"},
    {SurfaceKind::insulated, "insulated"},
});

/// One surface condition and the name its heat flow is reported under.
struct SurfaceCondition {
  std::string name;
  SurfaceKind kind = SurfaceKind::convection;
  double h = 0.0;            ///< convection coefficient [W/(m^2 K)]
  double ambient = 20.0;     ///< convection: temperature of the surroundings [deg C]
  double temperature = 0.0;  ///< fixed_temperature [deg C]
};

/// The thermal model of one problem. Every outer edge of the active regions (an edge of one
/// active triangle only) carries the surface condition of its boundary marker when
/// surface_of_boundary names one, else that of its region; edges on the axis of an
/// axisymmetric model are insulated (symmetry).
struct HeatModel {
  std::vector<HeatRegion> regions;
  std::vector<SurfaceCondition> surfaces;
  std::vector<int> surface_of_region;  ///< per region: index into surfaces of its outer edges
  /// Per Problem::boundaries entry: the surface of mesh edges with that marker, -1 (or a short
  /// vector) = by region.
  std::vector<int> surface_of_boundary;
};

}  // namespace rheomag::thermal
