#pragma once
// Steady coil and fluid temperatures of a design whose field is already solved (the optimiser's
// coil_temperature and fluid_temperature): one thermal factorisation, the coil's R(T) solved in
// closed form, the fluid's dissipation held at its value at the fluid's reference temperature.

#include "case/case_file.hpp"
#include "magnetostatics/solver.hpp"
#include "thermal/device_temperature.hpp"

namespace rheomag::thermal {

/// The heat of a solved design at its operating point.
struct DesignHeat {
  double coil_power = 0.0;         ///< I^2 R with R at `coil_temperature` [W]
  double coil_temperature = 20.0;  ///< the temperature of that R [deg C]
  double fluid_power = 0.0;        ///< dissipated in the gaps [W]
  double flow = 0.0;               ///< a valve's through-flow [m^3/s] (0: none)
  double duty = 1.0;               ///< fraction of the time at the operating point
  double copper_fill = 0.6;        ///< copper area / winding area
};

/// Temperature reported for a coil without a steady state (thermal runaway) [deg C]: finite, so
/// an optimiser sees a limit violated by far rather than a failed evaluation.
inline constexpr double kRunawayTemperature = 10000.0;

/// The steady temperatures of the design: its case's [thermal] surroundings, the field's mesh
/// and problem. The system is linear in the sources, so with T_c = a + b P(T_c) and copper's
/// P(T) = P20 (1 + 0.00393 (T - 20)) the coil's fixed point is exact; when b P20 0.00393 >= 1
/// there is none (runaway) and every temperature is kRunawayTemperature.
DeviceTemperatures design_temperatures(const cases::Case& c,
                                       const magnetostatics::MagnetostaticSolver& solver,
                                       const DesignHeat& heat);

}  // namespace rheomag::thermal
