// Steady temperatures of a solved design: two substitutions (a unit coil heat and the fluid's
// heat) on one factorisation, and copper's linear R(T) solved in closed form.

#include "thermal/design_temperature.hpp"

#include <cmath>

#include "core/error.hpp"
#include "thermal/device_regions.hpp"
#include "thermal/model_from_case.hpp"
#include "thermal/thermal_spec.hpp"
#include "valve/coil.hpp"

namespace rheomag::thermal {

constexpr double kCopperAlpha = valve::kCopperTemperatureCoefficient;

DeviceTemperatures design_temperatures(const cases::Case& c,
                                       const magnetostatics::MagnetostaticSolver& solver,
                                       const DesignHeat& heat) {
  const cases::Problem& problem = solver.problem();
  const ThermalSpec spec = read_thermal_spec(c);
  const std::vector<int> coil = coil_regions(problem), gaps = gap_regions(problem);
  const std::vector<double> volume = region_volumes(problem, solver.mesh());
  HeatModel model = build_heat_model(problem, spec, spec.copper_fill.value_or(heat.copper_fill));
  if (heat.flow > 0.0 && !gaps.empty()) {
    double gap_volume = 0.0;
    for (int r : gaps) gap_volume += volume[r];
    const cases::Material& fluid = problem.materials[problem.regions[gaps.front()].material];
    if (!fluid.thermal)
      throw InputError("thermal: the fluid '" + fluid.name + "' has no thermal data");
    for (int r : gaps) {
      model.regions[r].exchange = fluid.thermal->heat_capacity() * heat.flow / gap_volume;
      model.regions[r].exchange_temperature = spec.ambient;
    }
  }
  HeatSolver thermal(problem, solver.mesh(), std::move(model));
  // Response to 1 W in the coil (ambient included) and to the fluid's heat alone.
  std::vector<double> power(problem.regions.size(), 0.0);
  spread_power(1.0, coil, volume, power);
  thermal.set_sources(source_densities(power, volume));
  const DeviceTemperatures unit = temperatures_over(thermal.steady(), coil, gaps);
  power.assign(problem.regions.size(), 0.0);
  spread_power(heat.duty * heat.fluid_power, gaps, volume, power);
  thermal.set_sources(source_densities(power, volume));
  const DeviceTemperatures base = temperatures_over(thermal.steady(), coil, gaps);
  // unit - ambient is the rise per coil watt (the problem is linear; ambient appears once).
  const double b = unit.coil_mean - spec.ambient;
  const double p20 =
      heat.duty * heat.coil_power / (1.0 + kCopperAlpha * (heat.coil_temperature - 20.0));
  const double denominator = 1.0 - b * p20 * kCopperAlpha;
  DeviceTemperatures t;
  if (!(denominator > 0.0)) {
    t.coil_mean = t.coil_max = t.fluid_mean = t.fluid_max = kRunawayTemperature;
    return t;
  }
  const double coil_mean = (base.coil_mean + b * p20 * (1.0 - 20.0 * kCopperAlpha)) / denominator;
  // The coil's power at that temperature with the fluid's heat: the field of both (its maxima
  // are not the sums of the two fields' maxima).
  spread_power(p20 * (1.0 + kCopperAlpha * (coil_mean - 20.0)), coil, volume, power);
  thermal.set_sources(source_densities(power, volume));
  t = temperatures_over(thermal.steady(), coil, gaps);
  return t;
}

}  // namespace rheomag::thermal
