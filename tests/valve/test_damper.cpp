// Damper chain on the bundled piston case: the zero-field force against the mixed-mode law on
// the case's stated dimensions, the symmetry of the force in the velocity, the still-wall
// variant against the valve chain, and the field-on force rising with current.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "fluid/mixed_mode.hpp"
#include "valve/damper.hpp"
#include "valve/solved_valve.hpp"
#include "valve/valve_chain.hpp"

using namespace rheomag;

namespace {

const std::string kCase = std::string(RHEOMAG_SOURCE_DIR) + "/cases/damper_piston.toml";
constexpr double kPi = std::numbers::pi;

}  // namespace

// Reference: at I = 0 the field vanishes, so every gap sees tau_y(0) of MRF-132DG; the three gaps
// of cases/damper_piston.toml (r 19..20 mm, 6 + 16 + 6 mm long) are then one 28 mm annulus. With
// Q = pi (Rp^2 - Rr^2) v and U = -v (gap_wall = "cylinder"), F = dp A_eff + tau_w 2 pi Rp L +
// p_gas pi Rr^2 from fluid::annulus_mixed_mode directly (1e-6: trapezoid of a constant, exact).
// Reversing v reverses the force about the gas force (1e-9).
TEST(Damper, ZeroFieldForceIsTheMixedModeLaw) {
  const auto c = cases::load_case(kCase);
  const valve::DamperOptions options = valve::read_damper_options(c);
  valve::DamperChain chain(c, options);
  const double rp = 0.019, rr = 0.006, len = 0.028;
  const fluid::GapRheology f{chain.fluid().yield_stress(0.0), chain.fluid().viscosity,
                             chain.fluid().flow_index};
  const auto points = chain.evaluate({0.0}, {0.05, 0.5, -0.5});
  for (const auto& p : points) {
    const double v = p.velocity;
    const double a_eff = kPi * (rp * rp - rr * rr);
    const fluid::MixedModeDrop d = fluid::annulus_mixed_mode(
        fluid::AnnulusGeometry{0.001, rp + 0.0005, len}, f, -v, a_eff * v);
    const double ref =
        d.drop.dp * a_eff + d.moving_wall_force + options.gas_pressure * kPi * rr * rr;
    EXPECT_NEAR(p.force, ref, 1e-6 * std::abs(ref)) << v;
    EXPECT_NEAR(p.wall_velocity, -v, 1e-15);
  }
  EXPECT_NEAR(points[1].force - points[1].force_gas, -(points[2].force - points[2].force_gas),
              1e-9 * std::abs(points[1].force));
}

// Reference: with gap_wall = "piston" (both walls on the piston) the gaps carry Q = A_eff v with
// still walls, which is exactly the valve chain's problem: dp must equal ValveChain's dp_total
// at that flow in the same field (1e-8; both integrate the exact annulus law over the same
// samples).
TEST(Damper, StillWallVariantEqualsValveChain) {
  const auto c = cases::load_case(kCase);
  valve::DamperOptions options = valve::read_damper_options(c);
  options.gap_wall = valve::GapWall::piston;
  options.bore = 0.038;
  valve::DamperChain damper(c, options);
  valve::ValveChain chain(c, valve::read_valve_options(c));
  const double v = 0.1, area = kPi * (0.019 * 0.019 - 0.006 * 0.006);
  const auto d = damper.evaluate({1.0}, {v});
  const auto q = chain.evaluate({1.0}, {area * v});
  EXPECT_NEAR(d.front().dp / q.front().dp_total, 1.0, 1e-8);
  EXPECT_EQ(d.front().force_wall, 0.0);
}

// Design check of the bundled case (not a validation): at 1 A the pole gaps carry 0.4-1.1 T
// (the header's sizing: ~0.7 T); the force at 0.1 m/s rises monotonically from 0 to 1 A and the
// field-on force is several times the off-state damping force.
TEST(Damper, FieldOnForceRisesWithCurrent) {
  const auto c = cases::load_case(kCase);
  valve::DamperChain chain(c, valve::read_damper_options(c));
  const auto points = chain.evaluate({0.0, 0.5, 1.0}, {0.1});
  double previous = -1.0;
  for (const auto& p : points) {
    EXPECT_GT(p.force, previous);
    previous = p.force;
  }
  const auto& on = points.back();
  for (const auto& g : on.gaps)
    if (g.name != "gap_coil") {
      EXPECT_GT(g.drop.b_average, 0.4) << g.name;
      EXPECT_LT(g.drop.b_average, 1.1) << g.name;
    }
  EXPECT_GT((on.force - on.force_gas) / (points.front().force - points.front().force_gas), 3.0);
}

// Bad input: a case without [damper], an unknown gap_wall, a rod wider than the piston.
TEST(Damper, BadInput) {
  const auto valve_case =
      cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml");
  EXPECT_THROW(valve::read_damper_options(valve_case), InputError);
  const auto c = cases::load_case(kCase);
  valve::DamperOptions options = valve::read_damper_options(c);
  options.rod_diameter = 0.05;
  valve::DamperChain chain(c, options);
  EXPECT_THROW(chain.evaluate({0.0}, {0.1}), InputError);
}
