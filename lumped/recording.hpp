#pragma once
// A recording in the fixed format of shared/docs/recording-format.md: CSV samples + TOML sidecar.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/enum_names.hpp"

namespace rheomag::lumped {

/// The test rigs a recording can come from (docs/dynamics.md).
enum class RigKind { constant_velocity_pump, bypass_cylinder, damper, coil_bench };

/// The rig kinds' names as written in sidecars and specs.
inline constexpr auto kRigKindNames = enum_names<RigKind>({
    {RigKind::constant_velocity_pump, "constant_velocity_pump"},
    {RigKind::bypass_cylinder, "bypass_cylinder"},
    {RigKind::damper, "damper"},
    {RigKind::coil_bench, "coil_bench"},
});

/// The [rig] table of a sidecar (SI units). Absent optional keys stay empty.
struct RigInfo {
  std::optional<RigKind> kind;           ///< the [rig] kind, if the sidecar names one
  std::optional<double> piston_area;     ///< [m^2]
  std::optional<double> chamber_volume;  ///< [m^3]
  std::optional<double> rod_area;        ///< [m^2]
  std::optional<double> gas_force;       ///< [N]
  std::map<std::string, double> extra;   ///< any other numeric rig keys, as given
};

/// The [valve] table of a sidecar: an FE case or a Bingham static map.
struct ValveInfo {
  std::string case_file;               ///< path resolved against the sidecar's folder, or empty
  std::vector<double> yield_current;   ///< [A]
  std::vector<double> yield_pressure;  ///< [Pa]
  std::optional<double> viscous_resistance;  ///< [Pa s/m^3]
};

/// The [coil] table of a sidecar.
struct CoilInfo {
  std::optional<double> resistance;  ///< [ohm] at 20 degC
  std::optional<double> inductance;  ///< [H]
};

/// Everything in the TOML sidecar.
struct RecordingMeta {
  std::string description;
  std::vector<std::string> drive;  ///< names of the columns that drive the model
  std::string output;              ///< name of the column to explain
  RigInfo rig;
  ValveInfo valve;
  CoilInfo coil;
  std::string sidecar_path;
};

/// A recording: time base, named columns (all the same length as t), and its sidecar.
struct Recording {
  std::vector<double> t;                               ///< [s], strictly increasing
  std::map<std::string, std::vector<double>> columns;  ///< known columns only, SI
  RecordingMeta meta;
  std::string csv_path;
  std::vector<std::string> warnings;  ///< what the reader passed over (for the caller to show)

  /// The column `name`; throws InputError naming the file if it is absent.
  const std::vector<double>& column(const std::string& name) const;
  /// Throws InputError naming the file, the column and the samples when column `name` holds one
  /// value on every sample of [begin, end) (clamped to the data): a model of it is undefined.
  void require_varying(const std::string& name, std::size_t begin = 0,
                       std::size_t end = static_cast<std::size_t>(-1)) const;
};

}  // namespace rheomag::lumped
