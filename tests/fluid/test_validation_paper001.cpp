// Validation against paper 001's measured peak pressure drops (meandering valve, MRF-132DG,
// bypass-cylinder rig; /work/shared/seeds/001_*.txt, Fig. 7 and text): at 35.53, 53.30 and
// 71.06 ml/s the peak dp rises from 0.65, 0.95, 1.35 MPa at 0 A to 6.42, 6.53, 6.86 MPa at 1 A,
// predicted with the bundled meandering_valve case (FE field, MRF-132DG datasheet data,
// field-integrated exact Bingham gaps in series).
// Result (measured when written, see docs/validation.md): on-state (1 A) -11 % to -12 %
// unscaled; with ONE yield-stress scale for the valve (fitted to the on-state points only, since
// the scale cannot touch the viscous off-state) within 2 %. The off-state (0 A) is
// under-predicted about 3.7x: the chain has only the magnetised gaps' Poiseuille drop, not the
// valve's unmagnetised passages, fittings and entrance/exit losses, nor the fluid's shear
// thinning at these rates. The tolerances below pin both facts.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "fluid/valve_chain.hpp"
#include "magnetostatics/case_file.hpp"

using namespace rheomag;

TEST(ValidationPaper001, PeakPressureDropWithOneYieldStressScale) {
  const auto c =
      magnetostatics::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/meandering_valve.toml");
  fluid::ValveChain chain(c, fluid::ValveOptions{});
  const std::vector<double> flows{35.53e-6, 53.30e-6, 71.06e-6};
  const std::vector<double> measured_off{0.65e6, 0.95e6, 1.35e6};
  const std::vector<double> measured_on{6.42e6, 6.53e6, 6.86e6};
  const auto points = chain.evaluate({0.0, 1.0}, flows);  // current-major order
  ASSERT_EQ(points.size(), 6u);
  std::vector<double> on, off;
  for (std::size_t k = 0; k < flows.size(); ++k) {
    off.push_back(points[k].dp_total);
    on.push_back(points[flows.size() + k].dp_total);
  }
  // One scale s of the yield part minimising sum ((s p_yield + p_visc - m)/m)^2 over the
  // on-state points.
  double num = 0.0, den = 0.0;
  for (std::size_t k = 0; k < flows.size(); ++k) {
    const double y = points[flows.size() + k].dp_yield / measured_on[k];
    const double v = points[flows.size() + k].dp_viscous / measured_on[k];
    num += y * (1.0 - v), den += y * y;
  }
  const double scale = num / den;
  std::printf("paper 001: yield-stress scale %.3f\n", scale);
  for (std::size_t k = 0; k < flows.size(); ++k) {
    const auto& p = points[flows.size() + k];
    const double scaled = scale * p.dp_yield + p.dp_viscous;
    const double raw_error = on[k] / measured_on[k] - 1.0;
    const double scaled_error = scaled / measured_on[k] - 1.0;
    std::printf(
        "  Q=%.2f ml/s: 1 A measured %.2f MPa, predicted %.2f MPa (%+.1f %%), scaled %+.1f %%;"
        " 0 A measured %.2f MPa, predicted %.3f MPa (%+.0f %%)\n",
        flows[k] * 1e6, measured_on[k] * 1e-6, on[k] * 1e-6, 100 * raw_error, 100 * scaled_error,
        measured_off[k] * 1e-6, off[k] * 1e-6, 100 * (off[k] / measured_off[k] - 1.0));
    EXPECT_LT(std::abs(raw_error), 0.20) << "unscaled on-state, Q=" << flows[k];
    EXPECT_LT(std::abs(scaled_error), 0.05) << "scaled on-state, Q=" << flows[k];
    // Known gap: off-state predicted at 20-40 % of the measurement (see header).
    EXPECT_GT(off[k] / measured_off[k], 0.2) << "Q=" << flows[k];
    EXPECT_LT(off[k] / measured_off[k], 0.4) << "Q=" << flows[k];
  }
  EXPECT_GT(scale, 0.9);
  EXPECT_LT(scale, 1.3);
}
