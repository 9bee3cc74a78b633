#pragma once
// The [thermal] table of a case file (docs/thermal.md): surroundings, outer-surface conditions,
// the coil winding's make-up, material data the materials library lacks, and a temperature limit.

#include <optional>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "thermal/heat_model.hpp"

namespace rheomag::thermal {

/// [thermal] is a case-file section reserved for this layer.
inline const bool kThermalSectionRegistered = cases::register_case_section("thermal");

/// A [[thermal.surface]]: the condition on the outer surfaces of the named regions.
struct SurfaceRule {
  std::vector<std::string> regions;  ///< region names (as in the case)
  SurfaceCondition condition;
  std::string where;  ///< "file:line: thermal.surface[i]" for messages
};

/// A [[thermal.material]]: thermal data for a material of the case (overrides the library's).
struct MaterialThermal {
  std::string name;
  cases::ThermalProperties properties;
};

/// Everything [thermal] sets; the defaults hold without the table.
struct ThermalSpec {
  double ambient = 20.0;     ///< temperature of the surroundings [deg C]
  double convection = 10.0;  ///< h on every outer surface without a rule [W/(m^2 K)]
                             ///< (natural convection in still air: 5-25)
  double winding_matrix_conductivity = 0.2;  ///< enamel, varnish and voids between wires [W/(m K)]
  double winding_matrix_heat_capacity = 1.6e6;  ///< their rho c_p [J/(m^3 K)]
  std::optional<double> copper_fill;  ///< copper area / winding area when no wire is known
  std::optional<double> limit;        ///< largest allowed temperature [deg C]
  std::vector<SurfaceRule> surfaces;
  std::vector<MaterialThermal> materials;
};

/// Reads [thermal] (the defaults without it); InputError naming file, line and key: a negative
/// conductivity or convection coefficient, a fill outside (0, 0.907], an unknown region.
ThermalSpec read_thermal_spec(const cases::Case& c);

}  // namespace rheomag::thermal
