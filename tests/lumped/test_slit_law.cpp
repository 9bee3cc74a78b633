// The valve table's knee (lumped/slit_law.hpp): at slit_fraction 1 the table map is the exact
// slit law of a gap with the same Bingham asymptote, computed independently by
// fluid::slit_bingham (plug-fraction cubic by TOMS 748 from the gap's geometry); the map and its
// inverse agree; slit_fraction 0 is the Bingham line.

#include <gtest/gtest.h>

#include <cmath>

#include "fluid/slit_bingham.hpp"
#include "lumped/blocks.hpp"
#include "lumped/slit_law.hpp"

using namespace rheomag;
using rheomag::lumped::ValveMapBlock;

namespace {

// A slit 1 mm x 20 mm x 30 mm, 0.1 Pa s, yield stress 20 kPa: its Bingham line's intercept is
// 3 tau_y L / h and its slope 12 mu L / (b h^3).
constexpr double kGap = 1e-3, kWidth = 2e-2, kLength = 3e-2, kViscosity = 0.1, kTauY = 2e4;

ValveMapBlock slit_valve(double slit_fraction) {
  ValveMapBlock v;
  v.yield_current = {0.0, 1.0};
  const double intercept = 3.0 * kTauY * kLength / kGap;
  v.yield_pressure = {intercept, intercept};
  v.viscous_resistance = 12.0 * kViscosity * kLength / (kWidth * kGap * kGap * kGap);
  v.regularisation_flow = 1e-14;  // tanh(Q / eps) = 1 at every flow tested
  v.slit_fraction = slit_fraction;
  return v;
}

}  // namespace

// Reference: fluid::slit_bingham, the exact Bingham slit. Tolerance 1e-9 relative (both solve
// the same cubic to double precision, one in closed form, one by a bracketed root).
TEST(SlitLaw, FullSlitFractionIsTheExactSlitLaw) {
  const fluid::SlitGeometry g{kGap, kWidth, kLength};
  const ValveMapBlock v = slit_valve(1.0);
  for (double q : {1e-9, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3}) {
    const double exact = fluid::slit_bingham(g, kTauY, kViscosity, q).dp;
    EXPECT_NEAR(v.pressure_drop(q, 0.5), exact, 1e-9 * exact) << "Q = " << q;
    EXPECT_NEAR(v.pressure_drop(-q, 0.5), -exact, 1e-9 * exact) << "Q = " << -q;
  }
}

// The plug yields at 2/3 of the line's intercept (the slit's Q -> 0 limit, delta -> 1) and the map
// approaches the line at high flow (delta -> 0): the two ends of the knee.
TEST(SlitLaw, KneeRunsFromTwoThirdsOfTheInterceptToTheLine) {
  const ValveMapBlock v = slit_valve(1.0), line = slit_valve(0.0);
  const double intercept = v.yield_pressure[0];
  EXPECT_NEAR(v.pressure_drop(1e-12, 0.5), 2.0 / 3.0 * intercept, 1e-4 * intercept);
  const double fast = 1.0;  // R Q / p_y ~ 1e3: delta ~ 7e-4, the yield part within 1e-6 of p_y
  EXPECT_NEAR(v.pressure_drop(fast, 0.5), line.pressure_drop(fast, 0.5), 1e-6 * intercept);
  EXPECT_DOUBLE_EQ(slit_valve(0.0).pressure_drop(1e-6, 0.5),
                   intercept + line.viscous_resistance * 1e-6);
}

// The inverse map (flow at a pressure drop, used where chambers are compliant) returns the flow
// the map was evaluated at, for a partial and a full knee (tolerance 1e-7 relative: Newton stops
// at 1e-13 of the plug; the smooth ramp's tail, width R eps, is 1e-14 of the flow here).
TEST(SlitLaw, FlowInvertsThePressureDrop) {
  for (double k : {0.3, 1.0}) {
    ValveMapBlock v = slit_valve(k);
    v.regularisation_flow = 1e-16;
    for (double q : {1e-8, 1e-7, 1e-6, 1e-5, 1e-4}) {
      for (double s : {1.0, -1.0}) {
        const double dp = v.pressure_drop(s * q, 0.5);
        EXPECT_NEAR(v.flow(dp, 0.5), s * q, 1e-7 * q) << "k = " << k << ", Q = " << s * q;
      }
    }
    // Below the onset p_y (1 - k/3) nothing flows but the ramp's tail through the knee.
    const double onset = v.yield_pressure[0] * (1.0 - k / 3.0);
    EXPECT_LT(std::abs(v.flow(0.99 * onset, 0.5)), 1e-12);
    EXPECT_GT(v.flow(1.01 * onset, 0.5), 0.0);
    // Smooth and increasing across the onset (a kink there stalled the stiff integrator): the
    // flow's slope, by differences, never falls between neighbouring pressures.
    v.regularisation_flow = 1e-9;
    double last = 0.0, slope_before = -1.0;
    for (int j = -50; j <= 50; ++j) {
      const double dp = onset * (1.0 + 1e-3 * j), q = v.flow(dp, 0.5);
      if (j > -50) {
        const double slope = (q - last) / (1e-3 * onset);
        EXPECT_GE(slope, 0.0) << "k = " << k << ", dp = " << dp;
        EXPECT_GE(slope, slope_before * (1.0 - 1e-6)) << "k = " << k << ", dp = " << dp;
        slope_before = slope;
      }
      last = q;
    }
  }
}

// A yield tiny against the pressure (a current just above 0 A on a table that starts at 0 Pa):
// the flow is the line's, (excess - p_y / 3) / R above the onset p_y (1 - 1/3), finite for every
// ratio up to 1e300 (it was infinite once 1 - delta rounded to 1).
TEST(SlitLaw, TinyYieldGivesTheLinesFlow) {
  for (double py : {1e-3, 1e-100, 1e-300}) {
    const double e = 1e5, r = 1e10;
    const double q = lumped::knee_flow(e, py, r, 1.0);
    EXPECT_TRUE(std::isfinite(q)) << py;
    EXPECT_NEAR(q, (e - py / 3.0) / r, 1e-12 * e / r) << py;  // the line: onset + p_y / 3
  }
  // Either side of the switch between Q's two forms (u = 1/2), Q solves the knee's law.
  const double py = 1e6, r = 1e10;
  for (double e : {0.1e6, 0.2e6, 0.3e6, 1e6}) {
    const double q = lumped::knee_flow(e, py, r, 0.6);
    const double delta = lumped::slit_plug_at_flow(r * q / py);
    EXPECT_NEAR(r * q + 0.6 * py * (1.0 - delta * delta) / 3.0, e, 1e-9 * e) << e;
  }
}

// Closed form against the cubic it solves, across twelve decades of the flow ratio.
TEST(SlitLaw, PlugFractionSolvesItsCubic) {
  EXPECT_DOUBLE_EQ(lumped::slit_plug_at_flow(0.0), 1.0);
  for (double rho : {1e-8, 1e-4, 1e-2, 1.0, 1e2, 1e4}) {
    const double d = lumped::slit_plug_at_flow(rho);
    EXPECT_GT(d, 0.0);
    EXPECT_LE(d, 1.0);
    EXPECT_NEAR(d * d * d - 3.0 * (1.0 + rho) * d + 2.0, 0.0, 1e-10 * (1.0 + rho)) << rho;
  }
}
