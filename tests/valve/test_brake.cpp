// Brake chain on the bundled disc and drum cases: the zero-field torque against the closed
// forms on the cases' stated dimensions, and the torque rising with current.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "case/case_file.hpp"
#include "fluid/shear_mode.hpp"
#include "valve/brake.hpp"

using namespace rheomag;

namespace {
constexpr double kPi = std::numbers::pi;
}

// Reference: at I = 0 both gaps of cases/brake_disc.toml (plate r 8..40 mm, 1 mm each side) see
// tau_y(0): T = 2 x 2 pi [tau_y (Ro^3 - Ri^3)/3 + mu w (Ro^4 - Ri^4)/(4 h)] (1e-6).
TEST(Brake, DiscZeroFieldTorqueIsTheClosedForm) {
  const auto c = cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/brake_disc.toml");
  valve::BrakeChain chain(c, valve::read_brake_options(c));
  const double tau = chain.fluid().yield_stress(0.0), mu = chain.fluid().viscosity;
  const double ri = 0.008, ro = 0.040, h = 0.001;
  for (const auto& p : chain.evaluate({0.0}, {20.0})) {
    const double ref = 2.0 * 2.0 * kPi *
                       (tau * (ro * ro * ro - ri * ri * ri) / 3.0 +
                        mu * p.speed * (std::pow(ro, 4) - std::pow(ri, 4)) / (4.0 * h));
    EXPECT_NEAR(p.torque.torque, ref, 1e-6 * ref);
    EXPECT_EQ(p.gaps.size(), 2u);
  }
}

// Reference: at I = 0 the three gaps of cases/brake_drum.toml (r 30..31 mm, 10 + 20 + 10 mm)
// are one 40 mm drum at tau_y(0): fluid::drum_torque on those dimensions (1e-6).
TEST(Brake, DrumZeroFieldTorqueIsTheDrumLaw) {
  const auto c = cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/brake_drum.toml");
  valve::BrakeChain chain(c, valve::read_brake_options(c));
  const fluid::GapRheology f{chain.fluid().yield_stress(0.0), chain.fluid().viscosity, 1.0};
  for (const auto& p : chain.evaluate({0.0}, {5.0, 100.0})) {
    const double ref =
        fluid::drum_torque(fluid::DrumGeometry{0.030, 0.031, 0.040}, f, p.speed).torque;
    EXPECT_NEAR(p.torque.torque, ref, 1e-6 * ref);
  }
}

// Design check of the bundled cases: torque at 10 rad/s rises monotonically from 0 to 1 A, and
// the field-on torque is several times the off-state torque.
TEST(Brake, TorqueRisesWithCurrent) {
  for (const char* name : {"brake_disc", "brake_drum"}) {
    const auto c = cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/" + name + ".toml");
    valve::BrakeChain chain(c, valve::read_brake_options(c));
    const auto points = chain.evaluate({0.0, 0.5, 1.0}, {10.0});
    EXPECT_LT(points[0].torque.torque, points[1].torque.torque) << name;
    EXPECT_LT(points[1].torque.torque, points[2].torque.torque) << name;
    EXPECT_GT(points[2].torque.torque / points[0].torque.torque, 5.0) << name;
  }
}
