// A device's heat and temperatures: the fluid's temperature law and the coil's R(T) reach the
// chain, the duty scales the sources, the coupled fixed point is self-consistent, the valve's
// heat balance closes, and a transient ends at the steady state.

#include <gtest/gtest.h>

#include <cmath>

#include "case/case_file.hpp"
#include "thermal/thermal_report.hpp"
#include "valve/coil.hpp"

namespace rheomag::thermal {
namespace {

cases::Case valve_case() {
  return cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml");
}

ThermalReport at(const cases::Case& c, OperatingPoint point, std::optional<double> temperature) {
  ThermalRequest request;
  request.point = point;
  request.temperature = temperature;
  return run_thermal(c, request);
}

// MRC-C1L (cases/materials/mrc_c1l.toml): eta(T) = eta(40 C) exp(1960 K (1/T - 1/313.15 K)).
// At 0 A the valve's drop is purely viscous (Bingham with tau_y = 0: linear in eta), so the
// drop at 70 C over the drop at 40 C is that factor (to rounding).
TEST(DeviceHeat, ValveDropFollowsTheFluidsViscosityLaw) {
  const cases::Case c = valve_case();
  const OperatingPoint point{Motion::flow, 0.0, 1e-6, 1.0};
  const double at40 = at(c, point, 40.0).steady.heat.output;
  const double at70 = at(c, point, 70.0).steady.heat.output;
  const double expected = std::exp(1960.0 * (1.0 / 343.15 - 1.0 / 313.15));
  EXPECT_NEAR(at70 / at40, expected, 1e-9);
}

// Copper: R(T) / R(20 C) = 1 + 0.00393 (T - 20) (IACS, valve/coil.hpp); duty D scales I^2 R.
TEST(DeviceHeat, CoilPowerFollowsResistanceAndDuty) {
  const cases::Case c = valve_case();
  const ThermalReport cold = at(c, {Motion::none, 1.0, 0.0, 1.0}, 20.0);
  const ThermalReport hot = at(c, {Motion::none, 1.0, 0.0, 1.0}, 120.0);
  const ThermalReport half = at(c, {Motion::none, 1.0, 0.0, 0.5}, 120.0);
  EXPECT_NEAR(hot.steady.heat.coil_resistance / cold.steady.heat.coil_resistance,
              1.0 + 0.00393 * 100.0, 1e-12);
  EXPECT_NEAR(half.steady.heat.coil_power, 0.5 * hot.steady.heat.coil_power,
              1e-12 * hot.steady.heat.coil_power);
  EXPECT_DOUBLE_EQ(cold.steady.heat.coil_power, cold.steady.heat.coil_resistance);  // 1 A
}

// The coupled steady state: the coil's resistance is that of its own mean temperature (to the
// fixed point's 0.01 K), the heat balance closes to 1e-8 (issue 32), and it is hotter than
// ambient by what the surfaces and the through-flow carry away.
TEST(DeviceHeat, CoupledValveIsSelfConsistentAndBalanced) {
  const cases::Case c = valve_case();
  const ThermalReport cold = at(c, {Motion::none, 1.0, 0.0, 1.0}, 20.0);
  const ThermalReport r = at(c, {Motion::flow, 1.0, 1e-6, 1.0}, std::nullopt);
  ASSERT_TRUE(r.steady.coupled);
  EXPECT_GT(r.steady.iterations, 1);
  const double expected_r =
      cold.steady.heat.coil_resistance * (1.0 + 0.00393 * (r.steady.temperatures.coil_mean - 20.0));
  EXPECT_NEAR(r.steady.heat.coil_resistance, expected_r, expected_r * 0.00393 * 0.02);
  EXPECT_LT(std::abs(r.balance_error), 1e-8);
  const double carried = r.field.exchange_heat_flow + r.surface_heat_flow[0];
  EXPECT_NEAR(carried, r.steady.heat.coil_power + r.steady.heat.fluid_power, 1e-8 * carried);
  EXPECT_GT(r.steady.temperatures.coil_mean, r.ambient);
  EXPECT_GT(r.steady.temperatures.coil_max, r.steady.temperatures.coil_mean);
}

// A coupled transient from ambient ends at the coupled steady state (40 time constants of the
// slowest mode are well past: the end state is within 0.5 % of the steady rise).
TEST(DeviceHeat, TransientEndsAtTheSteadyState) {
  const cases::Case c = valve_case();
  ThermalRequest request;
  request.point = {Motion::none, 0.8, 0.0, 1.0};
  const ThermalReport steady = run_thermal(c, request);
  request.duration = 6.0 * 3600.0;
  request.steps = 360;
  request.limit = 0.5 * (steady.ambient + steady.steady.temperatures.coil_max);
  const ThermalReport transient = run_thermal(c, request);
  ASSERT_TRUE(transient.transient.has_value());
  const DeviceTemperatures end = transient.transient->samples.back().temperatures;
  const double rise = steady.steady.temperatures.coil_mean - steady.ambient;
  EXPECT_NEAR(end.coil_mean, steady.steady.temperatures.coil_mean, 0.005 * rise);
  ASSERT_TRUE(transient.transient->time_to_limit.has_value());
  EXPECT_GT(*transient.transient->time_to_limit, 0.0);
  EXPECT_LT(*transient.transient->time_to_limit, request.duration.value());
  double previous = -1e300;  // heating from ambient: the coil's mean never falls
  for (const DeviceSample& s : transient.transient->samples) {
    EXPECT_GE(s.temperatures.coil_mean, previous - 1e-9);
    previous = s.temperatures.coil_mean;
  }
}

}  // namespace
}  // namespace rheomag::thermal
