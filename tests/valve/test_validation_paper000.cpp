// Validation against paper 000's measured pressure amplitudes (Imaduddin et al., Micromachines
// 16 (2025) 144, sec. 4.1): 2.50, 4.89, 7.19, 8.5 bar at 5 mm/s and 2.39, 5.40, 7.40, 8.84 bar
// at 10 mm/s for 0.25, 0.5, 0.75, 1 A, predicted with the bundled annular_valve case (FE field,
// MRC-C1L extended data, field-integrated exact Bingham gaps).
// The rig's cylinder bore is not published, so the flow rate is unknown; at these Bingham
// numbers (~1e4-1e5) dp hardly depends on Q, which this test checks (1 vs 10 ml/s: < 3 %), and
// both speeds are predicted at Q = 1 ml/s (5 mm/s) and 2 ml/s (10 mm/s).
// Result (measured when written): unscaled the model over-predicts by +89 % to +140 %; with ONE
// yield-stress scale for the valve (least squares on relative errors) every point is within
// 15 % (worst -11 %). The scale and errors are printed; the tolerances below are the claim.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "case/case_file.hpp"
#include "valve/valve_chain.hpp"

using namespace rheomag;

TEST(ValidationPaper000, PressureAmplitudesWithOneYieldStressScale) {
  const auto c = cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml");
  valve::ValveChain chain(c, valve::ValveOptions{});
  const std::vector<double> currents{0.25, 0.5, 0.75, 1.0};
  const std::vector<double> measured_5{2.50e5, 4.89e5, 7.19e5, 8.5e5};
  const std::vector<double> measured_10{2.39e5, 5.40e5, 7.40e5, 8.84e5};
  const auto points = chain.evaluate(currents, {1e-6, 2e-6, 1e-5});
  std::vector<double> predicted, measured;
  for (std::size_t i = 0; i < currents.size(); ++i) {
    const auto& q1 = points[3 * i];
    const auto& q2 = points[3 * i + 1];
    const auto& q10 = points[3 * i + 2];
    EXPECT_LT(std::abs(q10.dp_total / q1.dp_total - 1.0), 0.03) << "I=" << currents[i];
    predicted.push_back(q1.dp_total), measured.push_back(measured_5[i]);
    predicted.push_back(q2.dp_total), measured.push_back(measured_10[i]);
  }
  // One scale s minimising sum ((s p - m)/m)^2; dp is ~ proportional to tau_y at Bi >> 1
  // (viscous part < 0.01 %), so scaling dp stands for scaling the yield-stress curve.
  double num = 0.0, den = 0.0;
  for (std::size_t k = 0; k < predicted.size(); ++k) {
    const double r = predicted[k] / measured[k];
    num += r, den += r * r;
  }
  const double scale = num / den;
  std::printf("paper 000: yield-stress scale %.3f\n", scale);
  for (std::size_t k = 0; k < predicted.size(); ++k) {
    const double raw = predicted[k] / measured[k] - 1.0;
    const double scaled = scale * predicted[k] / measured[k] - 1.0;
    std::printf(
        "  I=%.2f A %s: measured %.2f bar, predicted %.2f bar (%+.0f %%), scaled %+.1f %%\n",
        currents[k / 2], k % 2 ? "10 mm/s" : " 5 mm/s", measured[k] * 1e-5, predicted[k] * 1e-5,
        100 * raw, 100 * scaled);
    EXPECT_LT(std::abs(scaled), 0.15) << "point " << k;
  }
  // The unscaled over-prediction is a known, reported model/data gap (MRC-C1L tau_y(B) is
  // extended from one published point); pin its size so a change is noticed.
  EXPECT_GT(scale, 0.35);
  EXPECT_LT(scale, 0.65);
}
