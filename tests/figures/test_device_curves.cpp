// Points listed current-major become one curve per current, in order, with their own points.

#include <gtest/gtest.h>

#include "figures/device_curves.hpp"

using rheomag::figures::curves_per_current;

TEST(DeviceCurves, OneCurvePerRunOfEqualCurrents) {
  const auto p =
      curves_per_current("t", "v", "F", {0, 0, 0, 1, 1, 1, 2.5, 2.5, 2.5},
                         {1, 2, 3, 1, 2, 3, 1, 2, 3}, {10, 11, 12, 20, 21, 22, 30, 31, 32});
  ASSERT_EQ(p.series.size(), 3u);
  EXPECT_EQ(p.series[0].name, "I = 0 A");
  EXPECT_EQ(p.series[2].name, "I = 2.5 A");
  EXPECT_EQ(p.series[1].x, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(p.series[1].y, (std::vector<double>{20, 21, 22}));
  EXPECT_TRUE(p.series[2].markers);
}
