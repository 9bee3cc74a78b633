// Reader of the [thermal] table of a case file.

#include "thermal/thermal_spec.hpp"

#include "case/femm_sidecar.hpp"
#include "case/material_library.hpp"
#include "case/toml_section.hpp"
#include "core/error.hpp"

namespace rheomag::thermal {

namespace {

/// Temperatures of the surroundings and of fixed surfaces [deg C].
constexpr Domain kTemperature = Domain::between(-273.15, 2000.0, "deg C");

SurfaceRule read_surface(const cases::TomlSection& s, int index) {
  s.allow_only({"name", "regions", "convection", "ambient", "temperature", "insulated"});
  SurfaceRule rule;
  rule.where = s.where();
  rule.regions = s.strings("regions");
  if (rule.regions.empty()) s.fail("regions", "expected a list of region names");
  rule.condition.name = s.string("name").value_or("surface[" + std::to_string(index) + "]");
  const int kinds = s.has("convection") + s.has("temperature") + s.boolean_or("insulated", false);
  if (kinds != 1)
    s.fail("convection",
           "give exactly one of convection = h (with ambient), temperature = T or "
           "insulated = true");
  if (s.has("convection")) {
    rule.condition.kind = SurfaceKind::convection;
    rule.condition.h = s.quantity("convection", Domain::non_negative("W/(m^2 K)"));
  } else if (s.has("temperature")) {
    rule.condition.kind = SurfaceKind::fixed_temperature;
    rule.condition.temperature = s.quantity("temperature", kTemperature);
  } else {
    rule.condition.kind = SurfaceKind::insulated;
  }
  if (s.has("ambient") && rule.condition.kind != SurfaceKind::convection)
    s.fail("ambient", "ambient belongs to a convection surface");
  return rule;
}

}  // namespace

ThermalSpec read_thermal_spec(const cases::Case& c) {
  ThermalSpec spec;
  const cases::TomlSection top(c.table, "", cases::case_document_source(c));
  const std::optional<cases::TomlSection> thermal = top.table("thermal");
  if (!thermal) return spec;
  thermal->allow_only({"ambient", "convection", "winding_matrix_conductivity",
                       "winding_matrix_heat_capacity", "copper_fill", "limit", "surface",
                       "material"});
  spec.ambient = thermal->quantity_or("ambient", kTemperature, spec.ambient);
  spec.convection =
      thermal->quantity_or("convection", Domain::non_negative("W/(m^2 K)"), spec.convection);
  spec.winding_matrix_conductivity = thermal->quantity_or(
      "winding_matrix_conductivity", Domain::positive("W/(m K)"), spec.winding_matrix_conductivity);
  spec.winding_matrix_heat_capacity =
      thermal->quantity_or("winding_matrix_heat_capacity", Domain::positive("J/(m^3 K)"),
                           spec.winding_matrix_heat_capacity);
  // pi / (2 sqrt 3) = 0.907: hexagonal packing of round wire, the densest possible.
  spec.copper_fill =
      thermal->optional_quantity("copper_fill", Domain::between(0.0, 0.907).above(0.0));
  spec.limit = thermal->optional_quantity("limit", kTemperature);
  int index = 0;
  for (const cases::TomlSection& s : thermal->table_array("surface")) {
    SurfaceRule rule = read_surface(s, index++);
    if (rule.condition.kind == SurfaceKind::convection)
      rule.condition.ambient = s.quantity_or("ambient", kTemperature, spec.ambient);
    for (const std::string& name : rule.regions) {
      bool found = false;
      for (const mesh::RegionSeed& region : c.problem.geometry.regions)
        found = found || region.name == name;
      if (!found) s.fail("regions", "no region named '" + name + "' in the case");
    }
    spec.surfaces.push_back(std::move(rule));
  }
  for (const cases::TomlSection& s : thermal->table_array("material")) {
    s.allow_only({"name", "conductivity", "density", "specific_heat", "source", "uncertainty"});
    MaterialThermal m;
    m.name = s.required_string("name");
    m.properties = cases::read_thermal_properties(s);
    bool found = false;
    for (const cases::Material& material : c.problem.materials)
      found = found || cases::normalised_material_name(material.name) ==
                           cases::normalised_material_name(m.name);
    if (!found) s.fail("name", "no material named '" + m.name + "' in the case");
    spec.materials.push_back(std::move(m));
  }
  return spec;
}

}  // namespace rheomag::thermal
