#pragma once
// The materials library (cases/materials/*.toml) and the reader of material tables shared by
// library files and inline [[material]] tables of case files.

#include <toml++/toml.h>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "case/problem.hpp"
#include "case/toml_section.hpp"

namespace rheomag::cases {

/// A library material: its magnetic data plus the raw [rheology] table (read by the fluid link).
struct LibraryMaterial {
  Material magnetic;
  std::optional<toml::table> rheology;  ///< present for MR fluids
  std::string file;                     ///< the file it came from
};

/// Material names compare case-insensitively, ignoring spaces, '-' and '_' ("AISI 1010" =
/// "aisi-1010" = "aisi1010"); this is that normal form.
std::string normalised_material_name(std::string_view name);

/// Checks a B-H table given as (B [T], H [A/m]) pairs: at least 2 points, B and H strictly
/// increasing; (0, 0) is prepended when the table does not start there. InputError otherwise.
std::vector<BhPoint> checked_bh_table(const std::vector<std::pair<double, double>>& pairs,
                                      const std::string& where);

/// The keys of a material's [thermal] table.
inline const std::vector<std::string_view> kThermalKeys{"conductivity", "density", "specific_heat",
                                                        "source", "uncertainty"};

/// Reads the keys of a [thermal] table (the caller checks for unknown keys): conductivity
/// [W/(m K)], density [kg/m^3], specific_heat [J/(kg K)] (each > 0) and source; InputError
/// naming file, line and key otherwise.
ThermalProperties read_thermal_properties(const TomlSection& section);

/// Reads a material table (keys name, source, uncertainty, mu_r, bh, conductivity, rheology,
/// thermal).
LibraryMaterial read_material(const TomlSection& section);

/// All materials of one directory of TOML files, looked up by name.
class MaterialLibrary {
 public:
  /// Loads every *.toml file of `directory` (in file-name order); InputError on a bad file.
  static MaterialLibrary load(const std::filesystem::path& directory);
  /// The bundled library (an installed share/rheomag/materials, else RHEOMAG_MATERIALS_DIR),
  /// loaded once.
  static const MaterialLibrary& standard();

  /// Adds (or replaces, by name) one material.
  void add(LibraryMaterial material);
  /// The material of that name, nullptr if absent.
  const LibraryMaterial* find(std::string_view name) const;
  /// The material of that name; InputError "<where>: unknown material ..." with the closest name.
  const LibraryMaterial& get(std::string_view name, const std::string& where) const;
  /// Names of all materials.
  std::vector<std::string> names() const;

 private:
  std::vector<LibraryMaterial> materials_;
};

}  // namespace rheomag::cases
