// Paper 000's measured pressure rise times after a current step (sec. 4.1) against the physical
// constant-velocity rig (cases/rigs/constant_velocity_pump.toml: chamber compliance ahead of a
// Bingham plug + a field lag) and against the paper's own TF14 (Table 7).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "coupling/simulation_spec.hpp"
#include "lumped/signals.hpp"
#include "lumped/transfer_function.hpp"

#include <boost/math/tools/minima.hpp>

using namespace rheomag::lumped;
using namespace rheomag::coupling;

namespace {

constexpr double kStepTime = 0.5;  // [s] current switched from 0 to I here

/// 10-90 % rise time [s] of y after the step: from the first crossing of 10 % to the first of 90 %
/// of (final - initial), initial = value at the step, final = the given settled value.
double rise_time(const std::vector<double>& t, const std::vector<double>& y, double final_value) {
  double initial = 0.0, t10 = -1.0, t90 = -1.0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] <= kStepTime) {
      initial = y[k];
      continue;
    }
    const double f = (y[k] - initial) / (final_value - initial);
    if (t10 < 0 && f >= 0.1) t10 = t[k];
    if (t90 < 0 && f >= 0.9) t90 = t[k];
  }
  return t90 - t10;
}

Recording step_drive(double velocity, double current, double duration) {
  Recording drive;
  drive.t = uniform_times(duration, 1000.0);
  std::vector<double> v(drive.t.size(), velocity), i(drive.t.size(), 0.0);
  for (std::size_t k = 0; k < i.size(); ++k)
    if (drive.t[k] > kStepTime) i[k] = current;
  drive.columns["velocity"] = v;
  drive.columns["current"] = i;
  return drive;
}

const double kCurrents[] = {0.25, 0.5, 0.75, 1.0};
// Paper 000 sec. 4.1: 10-90 % pressure rise times [s] at 5 and 10 mm/s for 0.25 .. 1 A.
const double kMeasured5[] = {0.299, 0.572, 1.026, 1.164};
const double kMeasured10[] = {0.276, 0.415, 0.529, 0.605};

/// rms relative error of the 8 simulated rise times against paper 000's; `rise5`, `rise10` get
/// the simulated values [s].
double rise_time_rms(const SimulationSpec& spec, std::vector<double>* rise5 = nullptr,
                     std::vector<double>* rise10 = nullptr) {
  double sum_sq = 0.0;
  for (int v = 0; v < 2; ++v) {
    const double velocity = v == 0 ? 5e-3 : 10e-3;
    for (int k = 0; k < 4; ++k) {
      const Recording rec = simulate_spec(spec, step_drive(velocity, kCurrents[k], 5.0));
      const auto& p = rec.column("pressure");
      const double rise = rise_time(rec.t, p, p.back());
      const double error = rise / (v == 0 ? kMeasured5[k] : kMeasured10[k]) - 1.0;
      sum_sq += error * error;
      if (rise5 && rise10) (v == 0 ? rise5 : rise10)->push_back(rise);
    }
  }
  return std::sqrt(sum_sq / 8.0);
}

}  // namespace

// The physical rig with 2 chosen parameters (compliance 1.1e-11 m^3/Pa per chamber, 0.1 s field
// lag; yield pressures = the measured amplitudes) against the 8 measured rise times. Tolerances:
// each point within 30 % and the rms error within 18 % (measured: worst -24 %, rms 14 %, see
// docs/validation.md); the trend must be right: rise time grows with current at both velocities
// and is shorter at 10 mm/s than at 5 mm/s for every current.
TEST(RiseTimes, PhysicalRigExplainsPaper000) {
  const SimulationSpec spec = read_simulation_spec(std::string(RHEOMAG_SOURCE_DIR) +
                                                   "/cases/rigs/constant_velocity_pump.toml");
  std::vector<double> rise5, rise10;
  const double rms = rise_time_rms(spec, &rise5, &rise10);
  for (int k = 0; k < 4; ++k) {
    for (int v = 0; v < 2; ++v) {
      const double rise = v == 0 ? rise5[k] : rise10[k];
      const double measured = v == 0 ? kMeasured5[k] : kMeasured10[k];
      std::printf("%d mm/s %g A: simulated %.0f ms, measured %.0f ms (%+.0f %%)\n", v == 0 ? 5 : 10,
                  kCurrents[k], rise * 1e3, measured * 1e3, (rise / measured - 1.0) * 100);
      EXPECT_LT(std::abs(rise / measured - 1.0), 0.30) << v << ", " << kCurrents[k] << " A";
    }
  }
  EXPECT_LT(rms, 0.18);
  for (int k = 0; k < 4; ++k) {
    EXPECT_LT(rise10[k], rise5[k]) << kCurrents[k];
    if (k > 0) {
      EXPECT_GT(rise5[k], rise5[k - 1]);
      EXPECT_GT(rise10[k], rise10[k - 1]);
    }
  }
}

// TF14 is linear and has no velocity input: its 10-90 % rise time (to 90 % of the DC gain
// 7.485 bar/A x I) is the same at every current and velocity. Reference: its modal step response
// from Table 7's poles and residues, 292.3 ms (10 % at 27.4 ms, 90 % at 319.7 ms); tolerance 2 ms
// (1 kHz sampling). Equal for 0.25 and 1 A to 1e-9 s relative (linearity).
TEST(RiseTimes, Tf14RiseTimeIsOneNumber) {
  const TransferFunction tf = tf14_paper000();
  double rise_quarter = 0.0;
  for (double current : {0.25, 1.0}) {
    const Recording drive = step_drive(0.0, current, 2.5);
    const std::vector<double> p =
        simulate_transfer_function(tf, drive.t, drive.column("current"));  // bar
    const double rise = rise_time(drive.t, p, dc_gain(tf) * current);
    EXPECT_NEAR(rise, 0.2923, 0.002) << current;
    if (current == 0.25) rise_quarter = rise;
    if (current == 1.0) {
      EXPECT_NEAR(rise, rise_quarter, 1e-9);
    }
  }
}

// The rig with the field lag PREDICTED from the valve's FE model (eddy currents in its steel,
// cases/rigs/constant_velocity_pump_predicted.toml) and the chamber compliance the only fitted
// parameter: the bulk modulus minimising the rms error (Brent on log K over 0.3 .. 100 MPa) must
// be the one the rig file states (within 2 %), the rms error at it below 20 % and every point
// within 45 % (measured: rms 17.2 %, worst -42 % at 10 mm/s 0.25 A; docs/dynamics.md), the
// trends right as above.
TEST(RiseTimes, PredictedLagWithOnlyTheComplianceFitted) {
  SimulationSpec spec = read_simulation_spec(std::string(RHEOMAG_SOURCE_DIR) +
                                             "/cases/rigs/constant_velocity_pump_predicted.toml");
  ASSERT_TRUE(spec.rig && spec.rig->predicted_eddy_lag && spec.rig->compressibility);
  const PredictedLag& lag = *spec.rig->predicted_eddy_lag;
  ASSERT_EQ(lag.current.size(), 4u);
  for (std::size_t k = 0; k < lag.current.size(); ++k)
    std::printf("predicted field lag at %g A: %.1f ms\n", lag.current[k],
                lag.time_constant[k] * 1e3);
  const double stated = spec.rig->compressibility->bulk_modulus;
  auto rms_at = [&](double log_k) {
    spec.rig->compressibility->bulk_modulus = std::pow(10.0, log_k);
    return rise_time_rms(spec);
  };
  const auto [log_k, rms] = boost::math::tools::brent_find_minima(rms_at, 5.5, 8.0, 20);
  const double fitted = std::pow(10.0, log_k);
  spec.rig->compressibility->bulk_modulus = stated;
  std::vector<double> rise5, rise10;
  const double rms_stated = rise_time_rms(spec, &rise5, &rise10);
  std::printf("fitted bulk modulus %.4g Pa (rms %.1f %%); stated %.4g Pa (rms %.1f %%)\n", fitted,
              rms * 100, stated, rms_stated * 100);
  for (int k = 0; k < 4; ++k)
    std::printf("%g A: 5 mm/s %.0f / %.0f ms, 10 mm/s %.0f / %.0f ms\n", kCurrents[k],
                rise5[k] * 1e3, kMeasured5[k] * 1e3, rise10[k] * 1e3, kMeasured10[k] * 1e3);
  EXPECT_NEAR(fitted / stated, 1.0, 0.02);
  EXPECT_LT(rms_stated, 0.20);
  for (int k = 0; k < 4; ++k) {
    EXPECT_LT(std::abs(rise5[k] / kMeasured5[k] - 1.0), 0.45) << kCurrents[k];
    EXPECT_LT(std::abs(rise10[k] / kMeasured10[k] - 1.0), 0.45) << kCurrents[k];
    EXPECT_LT(rise10[k], rise5[k]) << kCurrents[k];
    if (k > 0) {
      EXPECT_GT(rise5[k], rise5[k - 1]);
    }
  }
}

// Rigs with an FE valve ([valve] case) take the predicted eddy-current lag by default: a rig
// file naming cases/annular_valve.toml and no [effects.eddy_currents] gets one lag per quarter
// of the case's 1 A (0.25 .. 1 A), each a positive time constant that does not grow with the
// current (saturation lowers the steel's incremental permeability); `enabled = false` turns it
// off.
TEST(RiseTimes, FeValveRigsUseThePredictedLagByDefault) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string valve_case = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";
  const std::string rig =
      "[rig]\nkind = \"constant_velocity_pump\"\nbore = 0.032\nrod = 0.012\n"
      "[driver]\nmode = \"current_source\"\n[valve]\ncase = \"" +
      valve_case + "\"\n";
  const auto on = dir / "rheomag_rig_predicted_default.toml";
  const auto off = dir / "rheomag_rig_predicted_off.toml";
  std::ofstream(on) << rig;
  std::ofstream(off) << rig << "[effects.eddy_currents]\nenabled = false\n";
  const SimulationSpec spec = read_simulation_spec(on.string());
  ASSERT_TRUE(spec.rig && spec.rig->predicted_eddy_lag);
  const PredictedLag& lag = *spec.rig->predicted_eddy_lag;
  ASSERT_EQ(lag.current.size(), 4u);
  EXPECT_DOUBLE_EQ(lag.current.front(), 0.25);
  EXPECT_DOUBLE_EQ(lag.current.back(), 1.0);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_GT(lag.time_constant[k], 0.0);
    if (k > 0) {
      EXPECT_LE(lag.time_constant[k], lag.time_constant[k - 1] * 1.01);
    }
  }
  EXPECT_DOUBLE_EQ(lag.at(0.1), lag.time_constant.front());  // held below the table
  EXPECT_FALSE(read_simulation_spec(off.string()).rig->predicted_eddy_lag);
  std::filesystem::remove(on);
  std::filesystem::remove(off);
}
