#pragma once
// The heat an MR device makes at one operating point, at given coil and fluid temperatures:
// the coil's I^2 R(T) and the fluid's dissipation (valve dp Q, damper F v, brake T w), placed
// on the regions of the device's mesh.

#include <memory>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "core/enum_names.hpp"
#include "valve/device_chain.hpp"

namespace rheomag::thermal {

/// What moves the fluid: nothing (a coil heating a still device), a valve's flow, a damper
/// piston's velocity or a brake rotor's speed.
enum class Motion { none, flow, velocity, speed };

/// Where a device works, and for what fraction of the time.
struct OperatingPoint {
  Motion motion = Motion::none;
  double current = 0.0;  ///< coil current [A]
  double value = 0.0;    ///< flow [m^3/s], velocity [m/s] or speed [rad/s]
  double duty = 1.0;     ///< fraction of the time at this point, in [0, 1]; the rest off and still
};

/// The heat of the device at one operating point, averaged over the duty cycle.
struct DeviceHeat {
  double coil_resistance = 0.0;      ///< at the coil temperature [Ohm]
  double coil_power = 0.0;           ///< duty x I^2 R [W]
  double fluid_power = 0.0;          ///< duty x the dissipation in the fluid [W]
  double output = 0.0;               ///< pressure drop [Pa], force [N] or torque [N m] at the point
  std::vector<double> region_power;  ///< per region of the field problem [W]
};

/// A device case set up once (mesh, field solver, gaps) and its heat at any temperatures.
/// The fluid's dissipation is spread over the fluid-gap regions: a valve gap segment's dp Q on
/// its own gap, a valve's passages and minor losses, a damper's F v (without the gas spring's
/// conservative force) and a brake's per-gap T w likewise, each uniformly over the gap's volume.
class DeviceHeatModel {
 public:
  /// InputError when the case lacks what the motion needs ([valve] wire for the coil's
  /// resistance, gaps, [damper] data) or the duty is outside [0, 1].
  DeviceHeatModel(const cases::Case& c, const OperatingPoint& point);
  ~DeviceHeatModel();
  /// The heat with the winding at `coil_celsius` and the fluid at `fluid_celsius` [deg C].
  DeviceHeat heat(double coil_celsius, double fluid_celsius);
  /// The device's field solver (its problem and mesh carry the thermal model).
  const magnetostatics::MagnetostaticSolver& solver() const { return chain_->solver(); }
  /// Regions of the coil (circuit, turns or a source current density).
  const std::vector<int>& coil_regions() const { return coil_regions_; }
  /// Fluid-gap regions.
  const std::vector<int>& gap_regions() const { return gap_regions_; }
  /// Copper area / winding area of the coil (from the wire and turns).
  double copper_fill() const { return copper_fill_; }
  /// Volume of each region of the field problem [m^3].
  const std::vector<double>& region_volume() const { return region_volume_; }
  /// The operating point.
  const OperatingPoint& point() const { return point_; }

 private:
  int gap_region(const std::string& name) const;  // -1 if no gap region has that name

  OperatingPoint point_;
  std::unique_ptr<valve::DeviceChain> chain_;
  std::vector<int> coil_regions_, gap_regions_;
  std::vector<double> region_volume_;  // [m^3]
  double copper_fill_ = 0.0;
};

}  // namespace rheomag::thermal
