// Paper 001's LuGre valve model (eqs. 8-9, Table 3) as a ready model: simulated on the paper's
// bypass rig it gives the peak pressure drops the paper measured.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "coupling/simulation_spec.hpp"
#include "lumped/lugre_paper001.hpp"
#include "lumped/signals.hpp"

using namespace rheomag::lumped;
using namespace rheomag::coupling;

// Table 3 at the ends of its range, evaluated by hand from the printed polynomials:
// A(0) = 0.0391, B(0) = 2.035, C(0) = 0.0683, alpha(0) = 1.2009; at 1 A the coefficient sums
// A = 0.6362, B = 35.725, C = 4.1442, alpha = 0.5085 (1e-9: exact arithmetic on the table).
TEST(LuGrePaper001, TableThreeAtZeroAndOneAmpere) {
  const LuGrePaper001Params p0 = lugre_paper001_params(0.0), p1 = lugre_paper001_params(1.0);
  EXPECT_NEAR(p0.A, 0.0391, 1e-9);
  EXPECT_NEAR(p0.B, 2.035, 1e-9);
  EXPECT_NEAR(p0.C, 0.0683, 1e-9);
  EXPECT_NEAR(p0.alpha, 1.2009, 1e-9);
  EXPECT_NEAR(p1.A, 0.6362, 1e-9);
  EXPECT_NEAR(p1.B, 35.725, 1e-9);
  EXPECT_NEAR(p1.C, 4.1442, 1e-9);
  EXPECT_NEAR(p1.alpha, 0.5085, 1e-9);
  EXPECT_EQ(p1.a0, 1.0);
}

// The bundled spec cases/rigs/lugre_paper001.toml on the paper's bypass rig (+-25 mm sine, piston
// area 452.4 mm^2, constant 0 or 1 A), peak |dp| over the third cycle against paper 001 sec. 3.2:
// 0.65 / 0.95 / 1.35 MPa at 0 A and 6.42 / 6.53 / 6.86 MPa at 1 A for 0.5 / 0.75 / 1 Hz (peak
// flows 35.53 / 53.30 / 71.06 ml/s, Fig. 7 caption; checked to 0.1 %). Tolerance 12 %: the table
// holds polynomial approximations of per-current fits (the paper's Fig. 9 shows their scatter),
// the fitted model itself has a mean RE of 7.6 % (Table 4), and the peaks are quoted as "around".
// Measured: +8.4, +7.0, 0.0 % (0 A) and -3.7, +3.6, +5.8 % (1 A).
TEST(LuGrePaper001, PeakPressureDropsOfThePaper) {
  const SimulationSpec spec =
      read_simulation_spec(std::string(RHEOMAG_SOURCE_DIR) + "/cases/rigs/lugre_paper001.toml");
  struct Point {
    double frequency, current, peak_flow, peak_dp;
  };
  const Point points[] = {{0.5, 0.0, 35.53e-6, 0.65e6},  {0.75, 0.0, 53.30e-6, 0.95e6},
                          {1.0, 0.0, 71.06e-6, 1.35e6},  {0.5, 1.0, 35.53e-6, 6.42e6},
                          {0.75, 1.0, 53.30e-6, 6.53e6}, {1.0, 1.0, 71.06e-6, 6.86e6}};
  for (const Point& pt : points) {
    Recording drive;
    drive.t = uniform_times(3.0 / pt.frequency, 400.0);
    add_signal(drive,
               "displacement=sine:amplitude=0.025,frequency=" + std::to_string(pt.frequency));
    add_signal(drive, "current=constant:value=" + std::to_string(pt.current));
    const Recording rec = simulate_spec(spec, drive);
    const auto& dp = rec.column("pressure");
    const auto& q = rec.column("flow");
    double peak_dp = 0.0, peak_q = 0.0;
    for (std::size_t k = 2 * dp.size() / 3; k < dp.size(); ++k) {
      peak_dp = std::max(peak_dp, std::abs(dp[k]));
      peak_q = std::max(peak_q, std::abs(q[k]));
    }
    EXPECT_NEAR(peak_q, pt.peak_flow, 1e-3 * pt.peak_flow) << pt.frequency;
    EXPECT_NEAR(peak_dp, pt.peak_dp, 0.12 * pt.peak_dp)
        << pt.frequency << " Hz, " << pt.current << " A";
  }
}
