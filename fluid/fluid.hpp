#pragma once
// An MR fluid's rheology (Bingham or Herschel-Bulkley) and the reader of the [rheology] table
// of a materials TOML file (format in docs/fluid.md).

#include <filesystem>
#include <string>
#include <string_view>

#include "case/case_sections.hpp"
#include "fluid/fluid_temperature.hpp"
#include "fluid/yield_stress.hpp"

namespace rheomag::fluid {

/// [fluid] is a case-file section reserved for this layer (docs/case-format.md).
inline const bool kFluidSectionRegistered = cases::register_case_section("fluid");

/// An MR fluid: tau = tau_y(B) + K gamma_dot^n (Bingham when n = 1 with K the plastic viscosity).
struct Fluid {
  std::string name;
  double viscosity = 0.1;           ///< plastic viscosity (n = 1) or consistency K [Pa s^n]
  double density = 3000.0;          ///< [kg/m^3]
  double flow_index = 1.0;          ///< Herschel-Bulkley exponent n (1 = Bingham)
  YieldStressCurve yield_stress;    ///< tau_y(|B|) [Pa]
  std::string source;               ///< where the data come from
  FluidTemperatureLaw temperature;  ///< how viscosity and yield stress follow the temperature
};

/// Parses the [rheology] table of a materials TOML document; `origin` names it in errors.
Fluid parse_fluid(std::string_view toml_text, const std::string& origin);

/// Reads the [rheology] table of a materials TOML file (throws InputError naming file and key).
Fluid read_fluid(const std::filesystem::path& file);

}  // namespace rheomag::fluid
