// B-H curve: interpolation, monotonicity, derivatives, B -> 0 limit, extrapolation, energy and
// validation of bad tables.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "magnetostatics/bh_curve.hpp"
#include "tests/magnetostatics/steel.hpp"

namespace rheomag::magnetostatics {
namespace {

TEST(BhCurve, ReproducesTheTablePoints) {
  // Reference: the table itself; tolerance 1e-9 relative (interpolation is exact at the nodes).
  const auto table = test::aisi1010().bh;
  ASSERT_GE(table.size(), 30u);
  const BhCurve curve(table, "AISI 1010");
  for (const cases::BhPoint& p : table) EXPECT_NEAR(curve.h(p.b), p.h, 1e-9 * (1.0 + p.h));
}

TEST(BhCurve, IsStrictlyMonotoneWithConsistentDerivatives) {
  // Reference: dH/dB, d nu/d(B^2) and H = dw/dB against central finite differences (step 1e-6 T,
  // tolerance 1e-5 relative); dH/dB > 0 everywhere (monotone interpolation, issue 2).
  const BhCurve curve(test::aisi1010().bh, "AISI 1010");
  double previous = -1.0;
  for (double b = 1e-4; b < 3.0; b += 0.00731) {
    const double h = curve.h(b);
    EXPECT_GT(h, previous) << "B = " << b;
    previous = h;
    EXPECT_GT(curve.dh_db(b), 0.0) << "B = " << b;
    const double step = 1e-6;
    const double fd_dh = (curve.h(b + step) - curve.h(b - step)) / (2 * step);
    EXPECT_NEAR(curve.dh_db(b), fd_dh, 1e-5 * fd_dh) << "B = " << b;
    const double b2 = b * b, step2 = 1e-6 * std::max(b2, 1e-2);
    const double fd_dnu = (curve.nu(b2 + step2) - curve.nu(b2 - step2)) / (2 * step2);
    EXPECT_NEAR(curve.dnu_db2(b2), fd_dnu, 1e-5 * std::abs(fd_dnu) + 1e-3) << "B = " << b;
    const double fd_w =
        (curve.energy_density(b + step) - curve.energy_density(b - step)) / (2 * step);
    EXPECT_NEAR(fd_w, h, 1e-5 * h) << "B = " << b;
    EXPECT_NEAR(curve.nu(b2) * b, h, 1e-9 * h);
  }
}

TEST(BhCurve, CombinedReluctivityAndSlopeEqualTheSeparateCalls) {
  // The element kernel's single evaluation must give exactly nu and dnu_db2 (bitwise: the same
  // arithmetic), over the first interval, the cubics and the extrapolation beyond the table.
  const BhCurve curve(test::aisi1010().bh, "AISI 1010");
  for (double b = 0.0; b < 4.0; b += 0.00731) {
    const auto [nu, dnu] = curve.nu_and_dnu_db2(b * b);
    EXPECT_EQ(nu, curve.nu(b * b)) << "B = " << b;
    EXPECT_EQ(dnu, curve.dnu_db2(b * b)) << "B = " << b;
  }
}

TEST(BhCurve, ReluctivityHasAFiniteLimitAtZero) {
  // Reference: nu(0) is the limit of H/B for B -> 0 (tolerance 1e-6 relative) and d nu/d(B^2)
  // is continuous there (no 1/B singularity).
  const BhCurve curve(test::aisi1010().bh, "AISI 1010");
  const double nu0 = curve.nu(0.0);
  EXPECT_TRUE(std::isfinite(nu0));
  EXPECT_GT(nu0, 0.0);
  EXPECT_NEAR(curve.h(1e-7) / 1e-7, nu0, 1e-6 * nu0);
  EXPECT_TRUE(std::isfinite(curve.dnu_db2(0.0)));
  EXPECT_NEAR(curve.dnu_db2(0.0), curve.dnu_db2(1e-8), 1e-9 * std::abs(curve.dnu_db2(0.0)) + 1e-9);
  EXPECT_EQ(curve.energy_density(0.0), 0.0);
}

TEST(BhCurve, ExtrapolatesTowardsVacuumPermeability) {
  // Reference: documented extrapolation H = H_n + x/mu0 + (d_n - 1/mu0) tau (1 - exp(-x/tau)),
  // x = B - B_n, tau = last table spacing: dH/dB continuous at B_n (1e-6 relative) and -> 1/mu0
  // (1e-9 relative at x = 40 tau); the magnetisation B/mu0 - H stays near iron's saturation.
  const auto table = test::aisi1010().bh;
  const BhCurve curve(table, "AISI 1010");
  const cases::BhPoint last = table.back();
  const double tau = last.b - table[table.size() - 2].b;
  EXPECT_NEAR(curve.dh_db(last.b + 1e-9), curve.dh_db(last.b - 1e-9), 1e-6 * curve.dh_db(last.b));
  EXPECT_NEAR(curve.dh_db(last.b + 40 * tau), kNu0, 1e-9 * kNu0);
  const double end_slope = curve.dh_db(last.b);
  for (double x : {0.01, 0.5, 3.0}) {
    const double expected = last.h + x / kMu0 + (end_slope - kNu0) * tau * (1 - std::exp(-x / tau));
    EXPECT_NEAR(curve.h(last.b + x), expected, 1e-9 * expected);
  }
  for (double x = 0.05; x < 2.0; x += 0.05) {
    const double m = (last.b + x) / kMu0 - curve.h(last.b + x);
    EXPECT_LT(m, 1.72e6);  // below the saturation magnetisation of iron (Ms ~ 1.71e6 A/m)
    EXPECT_GT(m, 1.5e6);
  }
}

TEST(BhCurve, TwoPointTableIsLinear) {
  // Reference: with the points (0, 0) and (1 T, 1000 A/m) the curve is H = 1000 B below 1 T
  // (tolerance 1e-12 relative); energy density 500 B^2.
  const BhCurve curve({{0.0, 0.0}, {1.0, 1000.0}}, "two-point");
  EXPECT_NEAR(curve.h(0.3), 300.0, 1e-9);
  EXPECT_NEAR(curve.nu(0.09), 1000.0, 1e-9);
  EXPECT_NEAR(curve.dnu_db2(0.09), 0.0, 1e-9);
  EXPECT_NEAR(curve.energy_density(0.5), 125.0, 1e-9);
}

void expect_input_error(const std::vector<cases::BhPoint>& table, const std::string& fragment) {
  try {
    BhCurve curve(table, "Steel-X");
    FAIL() << "no InputError for " << fragment;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("Steel-X"), std::string::npos) << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
  }
}

// A table read from a FEMM file is interpolated with FEMM's natural cubic spline (zero second
// derivative at both ends). Reference: the closed form of the natural spline through (0, 0),
// (1, 1), (2, 3): second derivative 1.5 at B = 1, so H = 0.25 B^3 + 0.75 B on [0, 1] and
// H = 0.25 (2 - B)^3 + 0.75 (2 - B) + 3 (B - 1) on [1, 2]; tolerance 1e-12. The monotone
// default differs from it by more than 1 % at B = 0.5 (it is another curve through the points).
TEST(BhCurve, FemmTablesFollowFemmsNaturalSpline) {
  const std::vector<cases::BhPoint> table{{0.0, 0.0}, {1.0, 1.0}, {2.0, 3.0}};
  const BhCurve femm(table, "femm", cases::BhInterpolation::femm_natural_spline);
  EXPECT_NEAR(femm.h(0.5), 0.40625, 1e-12);
  EXPECT_NEAR(femm.h(1.5), 1.90625, 1e-12);
  EXPECT_NEAR(femm.dh_db(0.0), 0.75, 1e-12);
  EXPECT_NEAR(femm.nu(0.0), 0.75, 1e-12);
  EXPECT_NEAR(femm.dh_db(1.5), 2.0625, 1e-12);
  EXPECT_NEAR(femm.energy_density(1.0), 0.4375, 1e-12);  // the integral of H on [0, 1]
  const BhCurve monotone(table, "monotone");
  EXPECT_GT(std::abs(monotone.h(0.5) / 0.40625 - 1.0), 0.01);
  // A table whose natural spline turns back keeps the monotone slopes: H rises everywhere.
  const std::vector<cases::BhPoint> kinked{{0.0, 0.0}, {1.0, 1.0}, {1.1, 50.0}, {2.0, 51.0}};
  const BhCurve safe(kinked, "kinked", cases::BhInterpolation::femm_natural_spline);
  const BhCurve reference(kinked, "kinked");
  for (double b = 0.01; b < 2.0; b += 0.01) {
    EXPECT_GT(safe.dh_db(b), 0.0) << b;
    EXPECT_EQ(safe.h(b), reference.h(b)) << b;
  }
}

TEST(BhCurve, RejectsBadTablesNamingTheMaterial) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  expect_input_error({{0.0, 0.0}}, "at least 2");
  expect_input_error({}, "at least 2");
  expect_input_error({{0.0, 0.0}, {1.0, 100.0}, {0.9, 200.0}}, "strictly increasing");
  expect_input_error({{0.0, 0.0}, {1.0, 100.0}, {1.1, 100.0}}, "strictly increasing");
  expect_input_error({{0.0, 0.0}, {nan, 100.0}}, "finite");
  expect_input_error({{0.0, 0.0}, {1.0, inf}}, "finite");
  expect_input_error({{0.0, 0.0}, {-1.0, 100.0}}, "finite non-negative");
}

}  // namespace
}  // namespace rheomag::magnetostatics
