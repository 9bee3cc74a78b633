// Fit metrics against hand-computed values.

#include <gtest/gtest.h>

#include <vector>

#include "core/error.hpp"
#include "lumped/metrics.hpp"

using namespace rheomag::lumped;

// y = [1,2,3,4], yhat = [1,2,3,5]: mean(y) = 2.5, ||y - mean|| = sqrt(2.25+0.25+0.25+2.25) =
// sqrt(5); ||y - yhat|| = 1. FIT = 100 (1 - 1/sqrt 5) = 55.27864045, RMSE% = 44.72135955,
// RE = 1/10 = 0.1. Tolerance 1e-9 (rounding only).
TEST(Metrics, HandComputedValues) {
  std::vector<double> y{1, 2, 3, 4}, yhat{1, 2, 3, 5};
  EXPECT_NEAR(fit_percent(y, yhat), 55.27864045000421, 1e-9);
  EXPECT_NEAR(rmse_percent(y, yhat), 44.72135954999579, 1e-9);
  EXPECT_NEAR(relative_error(y, yhat), 0.1, 1e-12);
  Metrics m = compute_metrics(y, yhat);
  EXPECT_NEAR(m.fit_percent + m.rmse_percent, 100.0, 1e-12);
}

// Signs count in RE: y = [-2, 2], yhat = [-1, 1] -> sum|e| = 2, sum|y| = 4, RE = 0.5;
// mean = 0, ||y|| = sqrt 8, ||e|| = sqrt 2 -> FIT = 50 %.
TEST(Metrics, SymmetricSignal) {
  std::vector<double> y{-2, 2}, yhat{-1, 1};
  Metrics m = compute_metrics(y, yhat);
  EXPECT_NEAR(m.fit_percent, 50.0, 1e-12);
  EXPECT_NEAR(m.re, 0.5, 1e-12);
}

// A model equal to the mean gives FIT 0; a perfect model gives FIT 100 and RE 0.
TEST(Metrics, MeanModelAndPerfectModel) {
  std::vector<double> y{1, 5, 3}, mean(3, 3.0);
  EXPECT_NEAR(fit_percent(y, mean), 0.0, 1e-12);
  EXPECT_NEAR(fit_percent(y, y), 100.0, 1e-12);
  EXPECT_NEAR(relative_error(y, y), 0.0, 1e-15);
}

// Range restricts the comparison: only samples 1..3 of the first test's data (y = [2,3,4]).
TEST(Metrics, RangeSelectsSamples) {
  std::vector<double> y{100, 2, 3, 4}, yhat{0, 2, 3, 5};
  // mean = 3, ||y - mean|| = sqrt 2, ||e|| = 1 -> FIT = 100 (1 - 1/sqrt 2) = 29.28932188
  Metrics m = compute_metrics(y, yhat, SampleRange{1, 4});
  EXPECT_NEAR(m.fit_percent, 29.289321881345245, 1e-9);
  EXPECT_NEAR(m.re, 1.0 / 9.0, 1e-12);
}

TEST(Metrics, BadInputThrows) {
  std::vector<double> c{2, 2, 2}, d{1, 2, 3}, s{1, 2};
  EXPECT_THROW(fit_percent(c, d), rheomag::InputError);
  EXPECT_THROW(fit_percent(d, s), rheomag::InputError);
  std::vector<double> z{0, 0};
  EXPECT_THROW(relative_error(z, s), rheomag::InputError);
}

TEST(Metrics, ParseSampleRange) {
  SampleRange r = parse_sample_range("0:2000", 3499, "--train");
  EXPECT_EQ(r.begin, 0u);
  EXPECT_EQ(r.end, 2000u);
  r = parse_sample_range("2000:", 3499, "--validate");
  EXPECT_EQ(r.end, 3499u);
  EXPECT_THROW(parse_sample_range("10", 100, "--train"), rheomag::InputError);
  EXPECT_THROW(parse_sample_range("0:200", 100, "--train"), rheomag::InputError);
  EXPECT_THROW(parse_sample_range("50:50", 100, "--train"), rheomag::InputError);
  EXPECT_THROW(parse_sample_range("a:5", 100, "--train"), rheomag::InputError);
}
