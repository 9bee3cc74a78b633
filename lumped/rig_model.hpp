#pragma once
// The test rigs of the papers composed from lumped blocks into one state-space model
// x' = f(x, u, t), y = g(x, u): driver -> coil (R(T), inductor or Duhem) -> eddy lag -> MR lag ->
// valve map -> chambers (compliance, air) and inertance -> pressure or damper force.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lumped/blocks.hpp"
#include "lumped/predicted_lag.hpp"
#include "lumped/recording.hpp"

namespace rheomag::lumped {

/// Rig layouts of the papers.

/// How the coil is fed.
enum class DriverMode {
  current_source,  ///< the recording's `current` is imposed (ideal current source)
  voltage,         ///< coil voltage = gain x `command` (or the `voltage` column)
  current_pi       ///< PI current control of `current_cmd` with a voltage limit
};

/// Everything a rig model needs; optional effects are off when empty.
struct RigSpec {
  RigKind kind = RigKind::bypass_cylinder;
  std::string description;
  double piston_area = 4.524e-4;  ///< [m^2]
  double rod_area = 0.0;          ///< [m^2] damper
  double gas_force = 0.0;         ///< [N] damper accumulator force offset
  DriverMode driver_mode = DriverMode::current_source;
  std::string voltage_column = "command";  ///< voltage mode: "command" or "voltage"
  DriverBlock driver;
  CoilBlock coil;
  ValveMapBlock valve;
  // Concealed effects (names as in the diagnosis output).
  std::optional<ChamberBlock> compressibility;    ///< compressibility (oil + air)
  std::optional<double> inertance;                ///< fluid_inertia [Pa s^2/m^3]
  std::optional<DuhemBlock> magnetic_hysteresis;  ///< magnetic_hysteresis
  std::optional<double> eddy_time_constant;       ///< eddy_currents [s]
  /// eddy_currents predicted from the valve's FE step responses: the lag's time constant at the
  /// current it is driven towards (takes the place of eddy_time_constant when set).
  std::optional<PredictedLag> predicted_eddy_lag;
  std::optional<ThermalBlock> coil_heating;  ///< coil_heating
  std::optional<FluidHeatingBlock>
      fluid_heating;                           ///< fluid_heating (column fluid_temperature_rise)
  std::optional<double> mr_response_time;      ///< mr_response_time [s]
  std::optional<double> coulomb_force;         ///< friction [N] (damper)
  double friction_velocity = 1e-3;             ///< [m/s] width of the friction tanh
  std::map<std::string, double> sensor_noise;  ///< column -> standard deviation (SI)
  unsigned noise_seed = 1;
  /// 0: adaptive rosenbrock4 (error-controlled); n > 0: n fixed SDIRK2 steps per sample
  /// interval (lumped/ode_grid.hpp: cost set by the samples, output smooth in the parameters),
  /// grid_edge_substeps in the intervals where a drive input steps (the grid follows the
  /// recording only, never the parameters). A spec with both compressibility and inertance (an
  /// LC circuit ringing faster than the samples) takes grid_edge_substeps in every interval.
  int grid_substeps = 0;
  int grid_edge_substeps = 8;
  /// Drive columns recorded as held samples: each sample stands for the interval it begins
  /// (zero-order hold), stepping to the next over the interval's last kHeldStepFraction (so that
  /// rates stay finite); the other drive columns are linear between samples.
  std::vector<std::string> held_drives;
};

/// Share of a sample interval over which a held drive column moves to its next sample.
inline constexpr double kHeldStepFraction = 0.125;

/// Parses "constant_velocity_pump" | "bypass_cylinder" | "damper" | "coil_bench".
bool parse_rig_kind(const std::string& name, RigKind& kind);

/// Name of a rig kind.
std::string rig_kind_name(RigKind kind);

/// Drive columns the rig reads from a recording (e.g. {"velocity", "current"}).
std::vector<std::string> rig_drive_columns(const RigSpec& spec);

/// Output column the rig explains ("pressure", "force" or "current").
std::string rig_output_column(const RigSpec& spec);

/// Simulates the rig driven by the drive columns of `drive` at its sample times (rosenbrock4, or
/// the fixed sample grid when spec.grid_substeps > 0),
/// adds the spec's sensor noise, and returns a recording (CSV columns + sidecar metadata). A valve
/// that names an FE case needs its map in spec.valve.chain (coupling::with_chain_map fills it):
/// InputError otherwise.
Recording simulate_rig(const RigSpec& spec, const Recording& drive);

}  // namespace rheomag::lumped
