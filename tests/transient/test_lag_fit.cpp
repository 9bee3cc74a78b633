// Reduced step responses: first-order lags fitted to a response.

#include <gtest/gtest.h>

#include <cmath>

#include "tests/transient/cylinder.hpp"
#include "transient/lag_fit.hpp"

namespace {

using rheomag::transient::fit_lags;
using rheomag::transient::lag_response;

// One exact exponential (tau = 20 ms, from 0.2 to 1.0) is recovered to 1e-6.
TEST(LagFit, RecoversOneExponential) {
  std::vector<double> t, y;
  for (int i = 0; i <= 100; ++i) {
    t.push_back(i * 1e-3);
    y.push_back(1.0 - 0.8 * std::exp(-t.back() / 0.02));
  }
  const auto lags = fit_lags(t, y, 0.2, 1.0, 1);
  ASSERT_EQ(lags.size(), 1u);
  EXPECT_NEAR(lags[0].time_constant / 0.02, 1.0, 1e-6);
  EXPECT_NEAR(lags[0].weight, 1.0, 1e-12);
}

// The cylinder's diffusion response (an infinite sum of lags, tau_1 = 108.6 ms, series of
// tests/transient/cylinder.hpp) sampled on [0, 0.6 s]: three lags reproduce it within 1 % of
// the change everywhere, and their slowest time constant is close to tau_1 (5 %).
TEST(LagFit, ThreeLagsReproduceTheCylinderDiffusion) {
  const rheomag::test::Cylinder c;
  std::vector<double> t, y;
  for (int i = 0; i <= 300; ++i) {
    t.push_back(i * 2e-3);
    y.push_back(c.relative_flux(t.back()));
  }
  const auto lags = fit_lags(t, y, 0.0, 1.0, 3);
  double worst = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i)
    worst = std::max(worst, std::abs(lag_response(lags, 0.0, 1.0, t[i]) - y[i]));
  EXPECT_LT(worst, 0.01);
  EXPECT_NEAR(lags.back().time_constant / c.tau1(), 1.0, 0.05);
  const auto one = fit_lags(t, y, 0.0, 1.0, 1);
  double worst_one = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i)
    worst_one = std::max(worst_one, std::abs(lag_response(one, 0.0, 1.0, t[i]) - y[i]));
  EXPECT_GT(worst_one, worst);  // one lag cannot follow the early sqrt(t) rise
}

}  // namespace
