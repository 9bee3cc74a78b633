// The fluid's temperature law: viscosity and yield-stress factors and the fluid at a temperature.

#include "fluid/fluid_temperature.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/format_text.hpp"
#include "fluid/fluid.hpp"

namespace rheomag::fluid {

namespace {

constexpr double kKelvinOffset = 273.15;

void check_temperature(double celsius) {
  const std::string problem = kFluidTemperature.violation(celsius);
  if (!problem.empty()) throw InputError("fluid temperature: " + problem);
}

}  // namespace

double FluidTemperatureLaw::viscosity_factor(double celsius) const {
  check_temperature(celsius);
  return std::exp(activation_temperature *
                  (1.0 / (celsius + kKelvinOffset) - 1.0 / (reference + kKelvinOffset)));
}

double FluidTemperatureLaw::yield_stress_factor(double celsius) const {
  check_temperature(celsius);
  const double factor = 1.0 + yield_stress_coefficient * (celsius - reference);
  if (!(factor > 0.0))
    throw InputError(
        format_text("fluid temperature %.6g C: the yield-stress derating "
                    "1 + %.6g/K x (T - %.6g C) reaches zero",
                    celsius, yield_stress_coefficient, reference));
  return factor;
}

Fluid fluid_at_temperature(const Fluid& fluid, double celsius) {
  if (fluid.temperature.constant()) {
    check_temperature(celsius);
    return fluid;
  }
  Fluid hot = fluid;
  hot.viscosity *= fluid.temperature.viscosity_factor(celsius);
  hot.yield_stress = fluid.yield_stress.scaled(fluid.yield_stress.scale() *
                                               fluid.temperature.yield_stress_factor(celsius));
  return hot;
}

}  // namespace rheomag::fluid
