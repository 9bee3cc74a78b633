// Paper 002's rotary damper as a bundled case (cases/rotary_damper_paper002.toml, dimensions
// chosen, the coil from the paper's 8.9 Ohm): the coil resistance, the zero-field torque against
// the paper's own torque model (its eq. 8) on the case's dimensions, and the torque-speed map at
// 0-1 A rising with current.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "case/case_file.hpp"
#include "valve/brake.hpp"

using namespace rheomag;

namespace {

constexpr double kPi = std::numbers::pi;

cases::Case rotary_case() {
  return cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/rotary_damper_paper002.toml");
}

}  // namespace

// Reference: paper 002 (RD-2028): coil resistance 8.9 Ohm. The case's 174 turns of AWG 30 in its
// coil window at 20 C must give it within 1 %.
TEST(RotaryDamperPaper002, CoilResistanceIsThePapers) {
  const auto c = rotary_case();
  valve::BrakeChain chain(c, valve::read_brake_options(c));
  const auto p = chain.evaluate({1.0}, {1.0}).front();
  const auto coil = chain.coil(1.0, p.inductance);
  EXPECT_NEAR(coil.resistance, 8.9, 0.01 * 8.9);
  EXPECT_GT(coil.time_constant, 0.0);
}

// Reference: paper 002 eq. 8 without friction, T = 2/3 pi tau_0 (R2^3 - R1^3) + pi eta w (R2^4 -
// R1^4) / (2 h) per sheared face (2 pi integral of r^2 tau over one face), twice for the case's
// two gaps, with R1 = 4 mm, R2 = 20 mm, h = 0.5 mm and at I = 0 tau_0 = tau_y(0)
// (tolerance 1e-6: the FE field is exactly zero at zero current).
TEST(RotaryDamperPaper002, ZeroFieldTorqueIsThePapersModel) {
  const auto c = rotary_case();
  valve::BrakeChain chain(c, valve::read_brake_options(c));
  const double tau = chain.fluid().yield_stress(0.0), eta = chain.fluid().viscosity;
  const double r1 = 0.004, r2 = 0.020, h = 0.0005;
  for (const auto& p : chain.evaluate({0.0}, {1.0, 10.0, 50.0})) {
    const double ref =
        2.0 * (2.0 / 3.0 * kPi * tau * (std::pow(r2, 3) - std::pow(r1, 3)) +
               kPi * eta * p.speed * (std::pow(r2, 4) - std::pow(r1, 4)) / (2.0 * h));
    EXPECT_NEAR(p.torque.torque, ref, 1e-6 * ref) << p.speed;
  }
}

// Torque-speed at 0, 0.25, 0.5, 0.75, 1 A (the paper's current range) and 1-50 rad/s: the torque
// rises with current at every speed and with speed at every current, the 1 A torque is more than
// 100 x the off-state torque at 10 rad/s (a shear-mode device's controllable range), and the
// field-on torque lies between the paper's model at tau_y(0) and at the fluid's largest yield
// stress (tau_y at 2 T: the curve's saturated end), both on the case's dimensions.
TEST(RotaryDamperPaper002, TorqueSpeedMapRisesWithCurrentAndSpeed) {
  const auto c = rotary_case();
  valve::BrakeChain chain(c, valve::read_brake_options(c));
  const std::vector<double> currents{0.0, 0.25, 0.5, 0.75, 1.0}, speeds{1.0, 10.0, 50.0};
  const auto points = chain.evaluate(currents, speeds);
  ASSERT_EQ(points.size(), currents.size() * speeds.size());
  const auto at = [&](std::size_t i, std::size_t k) { return points[i * speeds.size() + k]; };
  for (std::size_t k = 0; k < speeds.size(); ++k)
    for (std::size_t i = 1; i < currents.size(); ++i)
      EXPECT_GT(at(i, k).torque.torque, at(i - 1, k).torque.torque) << currents[i];
  for (std::size_t i = 0; i < currents.size(); ++i)
    for (std::size_t k = 1; k < speeds.size(); ++k)
      EXPECT_GT(at(i, k).torque.torque, at(i, k - 1).torque.torque) << speeds[k];
  EXPECT_GT(at(4, 1).torque.torque / at(0, 1).torque.torque, 100.0);
  const double r1 = 0.004, r2 = 0.020;
  const double yield_area = 2.0 * 2.0 / 3.0 * kPi * (std::pow(r2, 3) - std::pow(r1, 3));
  EXPECT_GT(at(4, 0).torque.breakaway_torque, yield_area * chain.fluid().yield_stress(0.0));
  EXPECT_LT(at(4, 0).torque.breakaway_torque, yield_area * chain.fluid().yield_stress(2.0));
}
