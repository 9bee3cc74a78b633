// The optimiser's steady temperatures (thermal/design_temperature.hpp: copper's R(T) solved in
// closed form on two substitutions) against the iterated fixed point of `rheomag thermal` on the
// same case: the same coil temperature to the iteration's tolerance; and a runaway is reported
// as kRunawayTemperature.

#include <gtest/gtest.h>

#include "case/case_file.hpp"
#include "thermal/design_temperature.hpp"
#include "thermal/thermal_report.hpp"

namespace rheomag::thermal {
namespace {

TEST(DesignTemperature, ClosedFormMatchesTheIteratedFixedPoint) {
  const cases::Case c =
      cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml");
  for (double current : {0.5, 1.5}) {
    ThermalRequest request;
    request.point = {Motion::none, current, 0.0, 1.0};
    const ThermalReport iterated = run_thermal(c, request);
    DeviceHeatModel device(c, request.point);
    const DeviceHeat cold = device.heat(20.0, 20.0);
    DesignHeat heat;
    heat.coil_power = cold.coil_power;
    heat.coil_temperature = 20.0;
    heat.copper_fill = device.copper_fill();
    const DeviceTemperatures closed = design_temperatures(c, device.solver(), heat);
    // The iteration stops when a mean moves by < 0.01 K; it converges geometrically, so it is
    // within a few hundredths of a kelvin of the exact fixed point.
    EXPECT_NEAR(closed.coil_mean, iterated.steady.temperatures.coil_mean, 0.05) << current;
    EXPECT_NEAR(closed.coil_max, iterated.steady.temperatures.coil_max, 0.05) << current;
  }
}

TEST(DesignTemperature, RunawayIsReportedAsAViolatedLimit) {
  const cases::Case c =
      cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml");
  DeviceHeatModel device(c, {Motion::none, 1.0, 0.0, 1.0});
  DesignHeat heat;
  heat.coil_power = 5e3;  // b P20 alpha >> 1 with the valve's ~15 K/W: no steady state
  heat.copper_fill = device.copper_fill();
  EXPECT_EQ(design_temperatures(c, device.solver(), heat).coil_mean, kRunawayTemperature);
}

}  // namespace
}  // namespace rheomag::thermal
