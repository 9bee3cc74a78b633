#pragma once
// `rheomag thermal`: a device case's temperatures at one operating point (steady, coupled or at
// a given temperature, or a transient from ambient), as text and JSON.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "core/progress.hpp"
#include "thermal/device_temperature.hpp"
#include "thermal/heat_model.hpp"
#include "thermal/thermal_network.hpp"

namespace rheomag::thermal {

/// What the user asks of `rheomag thermal`.
struct ThermalRequest {
  OperatingPoint point;
  std::optional<double> temperature;  ///< run the chain at this temperature [deg C]
  std::optional<double> duration;     ///< transient from ambient over this time [s]
  int steps = 200;                    ///< transient steps
  std::optional<double> ambient;      ///< overrides [thermal] ambient [deg C]
  std::optional<double> convection;   ///< overrides [thermal] convection [W/(m^2 K)]
  std::optional<double> limit;        ///< overrides [thermal] limit [deg C]
};

/// One region of the thermal model in a report.
struct RegionReport {
  std::string name;
  bool active = false;  ///< false: outside the thermal model (surroundings)
  double conductivity = 0.0, heat_capacity = 0.0, volume = 0.0;
  double power = 0.0;  ///< heat generated in it [W]
  RegionTemperature temperature;
};

/// The result of `rheomag thermal`.
struct ThermalReport {
  std::string case_name;
  OperatingPoint point;
  double ambient = 20.0;
  std::optional<double> limit;
  double copper_fill = 0.0;
  SteadyDevice steady;                       ///< empty solution when a transient was asked
  std::optional<DeviceTransient> transient;  ///< set when --duration was given
  std::vector<RegionReport> regions;
  std::vector<SurfaceCondition> surfaces;
  std::vector<double> surface_heat_flow;  ///< per surface [W] (of the reported state)
  double balance_error = 0.0;
  HeatSolution field;                     ///< the reported state (steady, or the transient's last)
  int unknowns = 0;                       ///< temperatures solved for
  std::optional<ThermalNetwork> network;  ///< the two-node network (a device with gaps)
  mesh::Mesh mesh;                        ///< the mesh of the field
  bool planar = false;                    ///< x-y (planar) rather than r-z (axisymmetric)
  std::vector<std::string> region_names;
};

/// Runs the thermal study of case `c`. InputError for bad input, ConvergenceError when no
/// steady temperature exists.
ThermalReport run_thermal(const cases::Case& c, const ThermalRequest& request);

/// The report as text (temperatures in deg C, powers in W).
std::string thermal_text(const ThermalReport& report);

/// The report as JSON (keys and units in docs/thermal.md).
nlohmann::json thermal_json(const ThermalReport& report);

/// Writes the thermal model's triangles with the temperature (point data "temperature", deg C)
/// and the heat source per cell ("heat_source", W/m^3) to a .vtu file, atomically.
void write_thermal_vtu(const ThermalReport& report, const std::string& path);

/// The name of a motion in outputs ("none", "flow", "velocity", "speed").
std::string motion_name(Motion motion);

}  // namespace rheomag::thermal
