// FEMM's smoothing of a B-H table whose spline turns back (case/femm_bh_smoothing.hpp). The
// references are scipy.interpolate.CubicSpline(B, H, bc_type="natural") (the spline FEMM fits),
// sampled at 400 001 points for the sign of dH/dB, with FEMM's three-point average repeated
// until it is positive throughout (FEMM's CMMaterialProp::GetSlopes, xfemm 35baec4).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "case/femm_bh_smoothing.hpp"

using rheomag::cases::femm_smoothed_bh_table;
using rheomag::cases::femm_spline_turns_back;
using Table = std::vector<std::pair<double, double>>;

// A saturation curve B = 1.6 tanh(H / 800 A/m) + mu0 H sampled at 12 points, and a straight
// line: their splines rise throughout (scipy: min dH/dB = 494 A/(m T) for the first), so FEMM
// uses them as given.
TEST(FemmBhSmoothing, ATableWhoseSplineRisesIsKept) {
  Table saturation, line;
  for (int i = 0; i < 12; ++i) {
    const double h = 5000.0 * i / 11.0;
    saturation.emplace_back(1.6 * std::tanh(h / 800.0) + 4e-7 * std::numbers::pi * h, h);
    line.emplace_back(0.1 * i, 250.0 * i);
  }
  for (const Table& t : {saturation, line}) {
    EXPECT_FALSE(femm_spline_turns_back(t));
    const auto smoothed = femm_smoothed_bh_table(t);
    EXPECT_EQ(smoothed.passes, 0);
    EXPECT_EQ(smoothed.points, t);
  }
}

// Monotone points whose natural spline still dips: scipy's slopes at the points are -333.3,
// 666.7, 666.7, -333.3. FEMM smooths such a table too, and so does rheomag.
TEST(FemmBhSmoothing, AMonotoneTableWhoseSplineDipsTurnsBack) {
  EXPECT_TRUE(femm_spline_turns_back({{0, 0}, {1, 0.001}, {2, 1000}, {3, 1000.001}}));
}

// One point that steps back (H 100 -> 90): scipy needs two passes of the average, after which
// the points are (0.65556, 86.667), (1.17778, 363.333), (1.6, 1008.889); the ends stay.
TEST(FemmBhSmoothing, APointThatStepsBackIsAveragedAsFemmDoes) {
  const Table table{{0, 0}, {1, 100}, {1.2, 90}, {1.5, 400}, {2, 2000}};
  EXPECT_TRUE(femm_spline_turns_back(table));
  const auto smoothed = femm_smoothed_bh_table(table);
  EXPECT_EQ(smoothed.passes, 2);
  const Table expected{{0, 0},
                       {0.6555555555555556, 86.66666666666667},
                       {1.1777777777777778, 363.3333333333333},
                       {1.6, 1008.888888888889},
                       {2, 2000}};
  ASSERT_EQ(smoothed.points.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(smoothed.points[i].first, expected[i].first, 1e-12) << i;
    EXPECT_NEAR(smoothed.points[i].second, expected[i].second, 1e-9) << i;
  }
  EXPECT_FALSE(femm_spline_turns_back(smoothed.points));
}

// A table whose B falls back is smoothed as well (FEMM's own test looks for dH/dB = 0 inside
// each interval and misses it); one whose ends cannot be joined by a rising curve stops at the
// pass limit and is returned still turning back, for the caller to refuse.
TEST(FemmBhSmoothing, FallingBIsSmoothedAndAnImpossibleTableStops) {
  const auto fixed = femm_smoothed_bh_table({{0, 0}, {1.0, 100}, {0.9, 200}, {1.5, 1000}});
  EXPECT_GT(fixed.passes, 0);
  EXPECT_FALSE(femm_spline_turns_back(fixed.points));
  const auto stuck = femm_smoothed_bh_table({{0, 0}, {0.5, 100}, {0.0, 200}}, 50);
  EXPECT_EQ(stuck.passes, 50);
  EXPECT_TRUE(femm_spline_turns_back(stuck.points));
}
