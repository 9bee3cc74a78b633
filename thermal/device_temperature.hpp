#pragma once
// A device's temperatures: steady (at a given temperature, or its own steady temperature found
// by iterating the thermal and the hydraulic-electric sides to a fixed point) and transient
// (sources following the temperature at every step), with the time to reach a limit.

#include <optional>
#include <string>
#include <vector>

#include "thermal/device_heat.hpp"
#include "thermal/heat_solver.hpp"

namespace rheomag::thermal {

/// Coil and fluid (the fluid gaps) temperatures of a solution [deg C].
struct DeviceTemperatures {
  double coil_mean = 0.0, coil_max = 0.0;
  double fluid_mean = 0.0, fluid_max = 0.0;
  /// The larger of the coil's and the fluid's maximum.
  double hottest() const { return coil_max > fluid_max ? coil_max : fluid_max; }
};

/// Volume-weighted mean temperature of `regions` in `solution` (NaN without regions).
double mean_over(const HeatSolution& solution, const std::vector<int>& regions);

/// Volume-weighted means and nodal maxima of the `coil` and `gaps` regions of `solution`.
DeviceTemperatures temperatures_over(const HeatSolution& solution, const std::vector<int>& coil,
                                     const std::vector<int>& gaps);

/// The coil and gap temperatures of `solution` (volume-weighted means, nodal maxima).
DeviceTemperatures device_temperatures(const HeatSolution& solution, const DeviceHeatModel& device);

/// The steady state of a device.
struct SteadyDevice {
  HeatSolution solution;
  DeviceHeat heat;  ///< the sources of `solution` (coupled: at the last iterate's temperatures)
  DeviceTemperatures temperatures;
  int iterations = 0;   ///< thermal solves made (1 when the temperature is given)
  bool coupled = true;  ///< false: the chain ran at a given temperature
};

/// How the steady chain is coupled to the temperature.
struct CouplingOptions {
  std::optional<double> temperature;  ///< run the chain at this temperature [deg C] (no iteration)
  double tolerance = 0.01;            ///< fixed point: largest change of a mean temperature [K]
  int max_iterations = 100;
};

/// The device's steady temperatures. Coupled: start at `ambient`, evaluate the heat at the
/// coil's and the fluid's mean temperatures, solve, repeat until both means change by less
/// than the tolerance. ConvergenceError (exit 3) when it does not settle: thermal runaway of
/// the coil at a fixed current, or a temperature outside the models' ranges.
SteadyDevice steady_device(DeviceHeatModel& device, HeatSolver& solver,
                           const CouplingOptions& options, double ambient);

/// One state of a device transient.
struct DeviceSample {
  double time = 0.0;  ///< [s]
  DeviceTemperatures temperatures;
  double coil_power = 0.0, fluid_power = 0.0;  ///< [W]
};

/// A device heating from ambient.
struct DeviceTransient {
  std::vector<DeviceSample> samples;    ///< the start and every step
  std::optional<double> time_to_limit;  ///< first time the hottest point reached the limit [s]
  HeatSolution last;
  /// Empty, or why the transient stopped before `duration` (the fluid or the coil left its
  /// model's temperature range).
  std::string stopped;
};

/// Heats the device from a uniform `ambient` for `duration` seconds in `steps` steps, the
/// sources evaluated at the current mean temperatures before every step. Without a fixed
/// `temperature` in `options` the sources follow the temperature; with it they are constant.
/// It stops early (DeviceTransient::stopped) when a temperature leaves the models' range.
DeviceTransient transient_device(DeviceHeatModel& device, HeatSolver& solver,
                                 const CouplingOptions& options, double ambient, double duration,
                                 int steps, std::optional<double> limit);

}  // namespace rheomag::thermal
