// Paper 004's damper as a bundled case (cases/damper_paper004.toml: internals chosen, the turns
// from the paper's flux linkage at 1 A) against what the paper publishes: the coil resistance, the
// flux linkage at 3.5 A and the force levels at its 0.15 m/s test speed. The paper identifies its
// damper from measurements without knowing its internals, so this is a comparison of levels on a
// plausible design, not a validation of the chain; docs/validation.md gives the table.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "case/case_file.hpp"
#include "valve/damper.hpp"

using namespace rheomag;

namespace {

// The paper's identified parameters at one peak current (its section 4): Duhem operator (eqs.
// 2-3) and force per flux linkage R(lambda).
struct PaperLevel {
  double peak_current, a, b1, b2, d, force_per_linkage;
};
constexpr PaperLevel kAt1A{1.0, 3.0, 0.03, 0.7, 0.015, 18.0e3};
constexpr PaperLevel kAt3p5A{3.5, 1.4, 0.08, 0.25, 0.004, 28.8e3};
constexpr double kViscousSlope = 120.0;  // paper 004: off-state R_v [N s/m]
constexpr double kTestSpeed = 0.15;      // 150 mm peak-to-peak triangle at 0.5 Hz [m/s]
constexpr double kForceRate = 15.0;      // paper 004: c [s/m] of tanh(c v)

// Flux linkage at the peak of the third cycle of a 1 Hz sine current through the paper's Duhem
// operator d lambda = a |di| (b1 tanh(b2 i) - lambda) + d di (explicit, 20 000 steps a cycle:
// converged to 1e-4 relative).
double paper_peak_linkage(const PaperLevel& p) {
  const int steps = 20000;
  double lambda = 0.0, peak = 0.0, previous = 0.0;
  for (int k = 1; k <= 3 * steps; ++k) {
    const double i = p.peak_current * std::sin(2.0 * std::numbers::pi * k / steps);
    const double di = i - previous;
    lambda += p.a * std::abs(di) * (p.b1 * std::tanh(p.b2 * previous) - lambda) + p.d * di;
    previous = i;
    if (k > 2 * steps) peak = std::max(peak, lambda);
  }
  return peak;
}

// The paper's force model (eq. 9) at the test speed with the gas force and friction removed.
double paper_force(const PaperLevel& p) {
  return kViscousSlope * kTestSpeed +
         p.force_per_linkage * paper_peak_linkage(p) * std::tanh(kForceRate * kTestSpeed);
}

cases::Case paper004_case() {
  return cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/damper_paper004.toml");
}

}  // namespace

// Reference: paper 004, coil 1.1 Ohm including connections. The case's winding (87 turns AWG 26,
// chosen from the flux linkage, not from the resistance) must give it within 10 %.
TEST(DamperPaper004, CoilResistanceIsThePapers) {
  const auto c = paper004_case();
  valve::DamperChain chain(c, valve::read_damper_options(c));
  const auto p = chain.evaluate({1.0}, {kTestSpeed}).front();
  EXPECT_NEAR(chain.coil(1.0, p.inductance).resistance, 1.1, 0.10 * 1.1);
}

// Reference: the paper's Duhem loops (parameters at 1 A and 3.5 A peak). At 1 A the turns were
// chosen from it (within 15 %); at 3.5 A the FE flux linkage is a prediction of the steel's
// saturation: within 15 %, and the ratio lambda(3.5 A)/lambda(1 A) (the paper's 2.86) within 20 %.
TEST(DamperPaper004, FluxLinkageFollowsThePapersLoops) {
  const auto c = paper004_case();
  valve::DamperChain chain(c, valve::read_damper_options(c));
  const auto points = chain.evaluate({1.0, 3.5}, {kTestSpeed});
  const double lambda1 = points[0].inductance * 1.0, lambda35 = points[1].inductance * 3.5;
  const double ref1 = paper_peak_linkage(kAt1A), ref35 = paper_peak_linkage(kAt3p5A);
  EXPECT_NEAR(lambda1, ref1, 0.15 * ref1);
  EXPECT_NEAR(lambda35, ref35, 0.15 * ref35);
  EXPECT_NEAR(lambda35 / lambda1, ref35 / ref1, 0.20 * ref35 / ref1);
}

// Reference: the paper's force model (eq. 9 with its identified R_v, c and R(lambda)) at its test
// speed, gas force removed. With internals unknown the comparison is of levels: the 1 A force
// within 25 %, the 3.5 A force and the off-state force within a factor of 3 (docs/validation.md
// explains the gaps: the fluid and the pole lengths are not known).
TEST(DamperPaper004, ForceLevelsAtTheTestSpeedMatchThePapersOrder) {
  const auto c = paper004_case();
  valve::DamperChain chain(c, valve::read_damper_options(c));
  const auto points = chain.evaluate({0.0, 1.0, 3.5}, {kTestSpeed});
  const auto rheomag_force = [&](std::size_t k) { return points[k].force - points[k].force_gas; };
  const double off = kViscousSlope * kTestSpeed;
  EXPECT_GT(rheomag_force(0), off / 3.0);
  EXPECT_LT(rheomag_force(0), off * 3.0);
  EXPECT_NEAR(rheomag_force(1), paper_force(kAt1A), 0.25 * paper_force(kAt1A));
  EXPECT_GT(rheomag_force(2), paper_force(kAt3p5A) / 3.0);
  EXPECT_LT(rheomag_force(2), paper_force(kAt3p5A) * 3.0);
}
