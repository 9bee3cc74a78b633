// Shear-mode torque: the disc's fully yielded formula, the drum's Reiner-Riwlin equation with
// partial yielding, the thin-gap limit, Herschel-Bulkley against Bingham and the power law.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "fluid/shear_mode.hpp"

using namespace rheomag::fluid;

namespace {
constexpr double kPi = std::numbers::pi;
}

// Reference: the fully yielded disc torque T = N 2 pi [tau_y (Ro^3 - Ri^3)/3 +
// mu omega (Ro^4 - Ri^4)/(4 h)] (1e-12), for either sign of omega, and the tau_y(r) overload
// with tau_y = a + b r against the exact N 2 pi [a (Ro^3-Ri^3)/3 + b (Ro^4-Ri^4)/4] (1e-10).
TEST(ShearMode, DiscFullyYieldedTorque) {
  const DiscGeometry g{0.012, 0.05, 0.8e-3, 2};
  const double tau_y = 3e4, mu = 0.11;
  for (double w : {-30.0, 0.5, 100.0}) {
    const double ref =
        g.faces * 2.0 * kPi *
        (tau_y * (std::pow(g.r_out, 3) - std::pow(g.r_in, 3)) / 3.0 +
         mu * std::abs(w) * (std::pow(g.r_out, 4) - std::pow(g.r_in, 4)) / (4.0 * g.gap));
    const ShearTorque t = disc_torque(g, GapRheology{tau_y, mu, 1.0}, w);
    EXPECT_NEAR(t.torque, std::copysign(ref, w), 1e-12 * ref);
    EXPECT_NEAR(t.torque_yield + t.torque_viscous, t.torque, 1e-12 * ref);
    EXPECT_EQ(t.yielded_fraction, 1.0);
  }
  const double a = 1e4, b = 4e5;
  const ShearTorque t = disc_torque(
      g, [&](double r) { return a + b * r; }, mu, 1.0, 10.0);
  const double yield_ref = g.faces * 2.0 * kPi *
                           (a * (std::pow(g.r_out, 3) - std::pow(g.r_in, 3)) / 3.0 +
                            b * (std::pow(g.r_out, 4) - std::pow(g.r_in, 4)) / 4.0);
  EXPECT_NEAR(t.torque_yield, yield_ref, 1e-10 * yield_ref);
}

// Reference: the defining integral of Couette flow, omega = int_{Ri}^{min(r_y,Ro)}
// (T/(2 pi L r^2) - tau_y)/(mu r) dr = T/(4 pi L mu) (1/Ri^2 - 1/rc^2) - (tau_y/mu) ln(rc/Ri),
// r_y = sqrt(T / (2 pi L tau_y)), evaluated at the torque the code returns must give back omega
// (1e-10) over partial and full yielding; the yield radius grows with speed and reaches r_out.
TEST(ShearMode, DrumReinerRiwlinWithPartialYielding) {
  const DrumGeometry g{0.02, 0.023, 0.03};
  const double tau_y = 2e4, mu = 0.1;
  double previous = 0.0;
  bool partial = false, full = false;
  for (double w : {0.01, 1.0, 30.0, 300.0, 3000.0, 30000.0}) {
    const ShearTorque t = drum_torque(g, GapRheology{tau_y, mu, 1.0}, w);
    const double ry = std::sqrt(t.torque / (2.0 * kPi * g.length * tau_y));
    const double rc = std::min(ry, g.r_out);
    const double omega =
        t.torque / (4.0 * kPi * g.length * mu) * (1.0 / (g.r_in * g.r_in) - 1.0 / (rc * rc)) -
        tau_y / mu * std::log(rc / g.r_in);
    // The two terms cancel at low speed: rounding of order 1e-14 of each term is allowed.
    EXPECT_NEAR(omega, w, 1e-10 * w + 1e-14 * tau_y / mu * (rc / g.r_in)) << w;
    EXPECT_NEAR(t.yield_radius, rc, 1e-12 * rc);
    EXPECT_GT(t.yielded_fraction, previous);
    previous = t.yielded_fraction;
    partial |= t.yielded_fraction < 1.0;
    full |= t.yielded_fraction == 1.0;
  }
  EXPECT_TRUE(partial);
  EXPECT_TRUE(full);
  // At rest: the breakaway torque 2 pi L tau_y Ri^2.
  EXPECT_NEAR(drum_torque(g, GapRheology{tau_y, mu, 1.0}, 0.0).torque,
              2.0 * kPi * g.length * tau_y * g.r_in * g.r_in, 1e-12);
}

// Reference: the thin-gap formula T = 2 pi R^2 L (tau_y + mu omega R / h) (R the mean radius)
// is the drum's limit for a small gap and a speed high enough to yield the whole gap; the
// relative difference must be below 2 h/R and fall with h (h/R = 0.02, 0.002).
TEST(ShearMode, DrumTendsToThinGapFormula) {
  const double r = 0.02, len = 0.03, tau_y = 2e4, mu = 0.1;
  double previous = 1.0;
  for (double h : {4e-4, 4e-5}) {
    const DrumGeometry g{r - h / 2, r + h / 2, len};
    const double w = 2000.0;
    const ShearTorque t = drum_torque(g, GapRheology{tau_y, mu, 1.0}, w);
    ASSERT_EQ(t.yielded_fraction, 1.0);
    const double thin = 2.0 * kPi * r * r * len * (tau_y + mu * w * r / h);
    const double err = std::abs(t.torque / thin - 1.0);
    EXPECT_LT(err, 2.0 * h / r) << h;
    EXPECT_LT(err, previous);
    previous = err;
  }
}

// Reference: the Herschel-Bulkley drum path (quadrature) against the Bingham closed form at
// n = 1 + 1e-9 (1e-7), and against the power-law closed form T = 2 pi L K [2 m omega /
// (Ri^-2m - Ro^-2m)]^n at tau_y = 0 (1e-10).
TEST(ShearMode, DrumHerschelBulkley) {
  const DrumGeometry g{0.02, 0.022, 0.03};
  for (double w : {0.05, 5.0, 500.0}) {
    const double bingham = drum_torque(g, GapRheology{2e4, 0.1, 1.0}, w).torque;
    EXPECT_NEAR(drum_torque(g, GapRheology{2e4, 0.1, 1.0 + 1e-9}, w).torque / bingham, 1.0, 1e-7);
    for (double n : {0.5, 1.5}) {
      const double m = 1.0 / n;
      const double ref =
          2.0 * kPi * g.length * 0.3 *
          std::pow(2.0 * m * w / (std::pow(g.r_in, -2.0 * m) - std::pow(g.r_out, -2.0 * m)), n);
      const ShearTorque t = drum_torque(g, GapRheology{0.0, 0.3, n}, w);
      EXPECT_NEAR(t.torque / ref, 1.0, 1e-10);
      EXPECT_NEAR(t.torque_viscous / ref, 1.0, 1e-12);
    }
  }
  EXPECT_NEAR(drum_torque(g, GapRheology{2e4, 0.1, 0.6}, -5.0).torque,
              -drum_torque(g, GapRheology{2e4, 0.1, 0.6}, 5.0).torque, 1e-9);
}

// Bad input: r_in >= r_out, gap <= 0, viscosity < 0, faces < 1 -> InputError; negative speed ok.
TEST(ShearMode, BadInput) {
  const GapRheology f{1e4, 0.1, 1.0};
  EXPECT_THROW(drum_torque(DrumGeometry{0.02, 0.02, 0.03}, f, 1.0), rheomag::InputError);
  EXPECT_THROW(drum_torque(DrumGeometry{0.03, 0.02, 0.03}, f, 1.0), rheomag::InputError);
  EXPECT_THROW(drum_torque(DrumGeometry{0.02, 0.021, 0.03}, GapRheology{1e4, -0.1, 1.0}, 1.0),
               rheomag::InputError);
  EXPECT_THROW(disc_torque(DiscGeometry{0.01, 0.05, 0.0, 2}, f, 1.0), rheomag::InputError);
  EXPECT_THROW(disc_torque(DiscGeometry{0.05, 0.01, 1e-3, 2}, f, 1.0), rheomag::InputError);
  EXPECT_THROW(disc_torque(DiscGeometry{0.01, 0.05, 1e-3, 0}, f, 1.0), rheomag::InputError);
  EXPECT_NO_THROW(disc_torque(DiscGeometry{0.01, 0.05, 1e-3, 2}, f, -1.0));
}
