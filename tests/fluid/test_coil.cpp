// Coil electrical model: wire gauges, resistance, fill, power and time constant.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fluid/coil.hpp"
#include "mesh/error.hpp"

using namespace rheomag::fluid;

// Reference: ASTM B258 table values: AWG 36 = 0.127 mm (definition), AWG 24 = 0.5106 mm,
// AWG 0000 = 11.684 mm (4 decimals of mm as tabulated).
TEST(Coil, AwgDiameters) {
  EXPECT_NEAR(awg_diameter(36), 0.127e-3, 1e-12);
  EXPECT_NEAR(awg_diameter(24), 0.5106e-3, 0.00005e-3);
  EXPECT_NEAR(awg_diameter(-3), 11.684e-3, 0.0005e-3);
  EXPECT_EQ(wire_diameter("AWG 24"), awg_diameter(24));
  EXPECT_EQ(wire_diameter("24 awg"), awg_diameter(24));
  EXPECT_EQ(wire_diameter("awg0000"), awg_diameter(-3));
  EXPECT_NEAR(wire_diameter("0.5 mm"), 0.5e-3, 1e-15);
  EXPECT_THROW(wire_diameter("AWG 99"), rheomag::InputError);
  EXPECT_THROW(wire_diameter("thick"), rheomag::InputError);
  EXPECT_THROW(wire_diameter("-1 mm"), rheomag::InputError);
  EXPECT_THROW(wire_diameter("AWG 2.5"), rheomag::InputError);
}

// Reference: AWG 24 copper is 84.2 mOhm/m at 20 C (standard wire tables); the paper-000 coil
// (600 turns, mean turn 2 pi 15 mm, cases/annular_valve.toml header) is then ~4.76 Ohm.
// R(T) = R20 (1 + 0.00393 (T - 20)); P = I^2 R; tau = L/R; J = I/(pi d^2/4).
TEST(Coil, ResistancePowerTimeConstant) {
  const double d = awg_diameter(24);
  EXPECT_NEAR(copper_resistivity(20.0) / (std::numbers::pi * d * d / 4.0), 84.2e-3, 0.1e-3);
  CoilSpec spec{600, d, 2.0 * std::numbers::pi * 15e-3, 32e-3 * 7e-3, 20.0};
  const auto cold = coil_properties(spec, 1.0, 0.05);
  EXPECT_NEAR(cold.resistance, 4.76, 0.02);
  EXPECT_NEAR(cold.power, cold.resistance, 1e-12);
  EXPECT_NEAR(cold.time_constant, 0.05 / cold.resistance, 1e-15);
  EXPECT_NEAR(cold.current_density, 1.0 / (std::numbers::pi * d * d / 4.0), 1e-6);
  EXPECT_NEAR(cold.copper_fill, 600 * std::numbers::pi * d * d / 4.0 / (32e-3 * 7e-3), 1e-12);
  spec.temperature = 70.0;
  EXPECT_NEAR(coil_properties(spec, 1.0, 0.05).resistance / cold.resistance, 1.0 + 0.00393 * 50.0,
              1e-12);
  EXPECT_NEAR(coil_properties(spec, 2.0, 0.05).power / coil_properties(spec, 1.0, 0.05).power, 4.0,
              1e-12);
}

TEST(Coil, BadInputThrows) {
  const double d = awg_diameter(24);
  EXPECT_THROW(coil_properties(CoilSpec{0, d, 0.1, 1e-4, 20}, 1.0, 0.01), rheomag::InputError);
  EXPECT_THROW(coil_properties(CoilSpec{600, d, 0.1, 1e-6, 20}, 1.0, 0.01),
               rheomag::InputError);  // does not fit the window
  EXPECT_THROW(coil_properties(CoilSpec{600, d, 0.1, 1e-3, 20}, 1.0, -1.0), rheomag::InputError);
  EXPECT_THROW(copper_resistivity(-300.0), rheomag::InputError);
}
