// The thermal model of a problem from its materials and the [thermal] table.

#include "thermal/model_from_case.hpp"

#include "case/material_library.hpp"
#include "core/error.hpp"
#include "core/format_text.hpp"

namespace rheomag::thermal {

Conduction winding_conduction(const Conduction& wire, const Conduction& matrix, double fill) {
  if (!(fill > 0.0 && fill < 1.0))
    throw InputError(format_text("thermal model: copper fill must be in (0, 1), got %.6g", fill));
  const double sum = wire.conductivity + matrix.conductivity;
  const double diff = fill * (wire.conductivity - matrix.conductivity);
  return {matrix.conductivity * (sum + diff) / (sum - diff),
          fill * wire.heat_capacity + (1.0 - fill) * matrix.heat_capacity};
}

namespace {

/// The thermal data of `material`: spec.materials first, then the material's own.
std::optional<cases::ThermalProperties> thermal_data(const cases::Material& material,
                                                     const ThermalSpec& spec) {
  for (const MaterialThermal& m : spec.materials)
    if (cases::normalised_material_name(m.name) == cases::normalised_material_name(material.name))
      return m.properties;
  return material.thermal;
}

}  // namespace

HeatModel build_heat_model(const cases::Problem& problem, const ThermalSpec& spec,
                           double copper_fill) {
  HeatModel model;
  model.surfaces.push_back(
      {"outer surfaces", SurfaceKind::convection, spec.convection, spec.ambient, 0.0});
  model.regions.assign(problem.regions.size(), HeatRegion{});
  model.surface_of_region.assign(problem.regions.size(), 0);
  for (std::size_t r = 0; r < problem.regions.size(); ++r) {
    const cases::RegionData& data = problem.regions[r];
    const mesh::RegionSeed& seed = problem.geometry.regions[r];
    if (seed.hole || data.material < 0) continue;
    const cases::Material& material = problem.materials[data.material];
    const std::optional<cases::ThermalProperties> props = thermal_data(material, spec);
    const bool coil = data.circuit >= 0 || data.turns != 0.0 || data.current_density != 0.0;
    if (!props) {
      if (coil || seed.gap != mesh::GapKind::none)
        throw InputError("thermal model: region '" + seed.name + "' (" +
                         (coil ? "a coil" : "a fluid gap") + ") has material '" + material.name +
                         "' without thermal data; add a [thermal] table to its material file "
                         "or a [[thermal.material]] with its name");
      continue;
    }
    HeatRegion& region = model.regions[r];
    region.active = true;
    Conduction c{props->conductivity, props->heat_capacity()};
    if (coil)
      c = winding_conduction(
          c, {spec.winding_matrix_conductivity, spec.winding_matrix_heat_capacity}, copper_fill);
    region.conductivity = c.conductivity;
    region.heat_capacity = c.heat_capacity;
  }
  for (const SurfaceRule& rule : spec.surfaces) {
    const int index = static_cast<int>(model.surfaces.size());
    model.surfaces.push_back(rule.condition);
    for (const std::string& name : rule.regions)
      for (std::size_t r = 0; r < problem.regions.size(); ++r)
        if (problem.geometry.regions[r].name == name) {
          if (!model.regions[r].active)
            throw InputError(rule.where + ": region '" + name +
                             "' is outside the thermal model (its material has no thermal data)");
          model.surface_of_region[r] = index;
        }
  }
  return model;
}

}  // namespace rheomag::thermal
