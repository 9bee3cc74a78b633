// A sweep of 10^7 designs would run for months: once its first designs give the pace, it says
// so, with the estimate and how to stop, resume or split it (issue #36: 10^7 designs started
// without a word).

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "sweep/progress.hpp"

using namespace rheomag::sweep;

// 3 designs in 3 s, 10^7 in all: 9 999 997 s left = 115.7 days.
TEST(SweepLongRun, RunOfMonthsIsWarnedWithItsEstimate) {
  const std::string w = long_run_warning(3, 10'000'000, 3.0);
  EXPECT_NE(w.find("the remaining 9999997 take about 115.7 days"), std::string::npos) << w;
  EXPECT_NE(w.find("--shard"), std::string::npos) << w;
}

// Under a day (3 designs in 3 s of 80 000: 22 h), or no pace yet (2 designs in 1 s): silent.
TEST(SweepLongRun, RunOfHoursOrNoPaceYetIsNotWarned) {
  EXPECT_EQ(long_run_warning(3, 80'000, 3.0), "");
  EXPECT_EQ(long_run_warning(2, 10'000'000, 1.0), "");
  EXPECT_EQ(long_run_warning(0, 10'000'000, 100.0), "");
}

// The progress object asks the same question: 10^7 designs of microseconds each finish in
// seconds, so nothing is printed about them.
TEST(SweepLongRun, FastDesignsAreNotWarnedAbout) {
  std::ostringstream out;
  SweepProgress progress(10'000'000, &out, false);
  for (int k = 0; k < 5; ++k) progress.record(true);
  EXPECT_EQ(out.str().find("warning"), std::string::npos) << out.str();
}
