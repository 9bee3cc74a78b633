// The fluid_inertia candidate started from the ringing a compliant baseline leaves: with the
// stated oil's compliance C in the baseline, an inertance I rings at omega^2 = 1 / (I C), so the
// error is multimodal in I and the decade grid alone can start in the wrong mode.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "diagnose/diagnose_ringing.hpp"
#include "test_diagnose_fixture.hpp"

namespace {

// A drive sine at 4 Hz; the residual a damped 61 Hz ringing restarted every half drive period (a
// comb of drive harmonics under a resonance) plus a third drive harmonic as strong as a map error
// leaves. Both are above the drive band, so both are returned (the diagnosis scores every start
// by the simulated error and keeps the best). Reference: the generating frequencies; tolerance
// 2 % (the ring's comb lines are 8 Hz = 13 % apart: its strongest line alone would be 64 Hz,
// 5 % off; the power-weighted mean of its +-10 % lands within 0.3 %).
TEST(DiagnoseRinging, FrequencyOfARestartedRing) {
  const double dt = 5e-4, f_drive = 4.0, f_ring = 61.0, decay = 15.0;
  std::vector<double> drive, residual;
  for (int k = 0; k < 4000; ++k) {
    const double t = k * dt;
    drive.push_back(0.05 * std::sin(2.0 * std::numbers::pi * f_drive * t));
    const double since = std::fmod(t, 0.5 / f_drive);
    residual.push_back(std::exp(-decay * since) *
                           std::sin(2.0 * std::numbers::pi * f_ring * since) +
                       0.3 * std::sin(2.0 * std::numbers::pi * 3.0 * f_drive * t));
  }
  const auto f = rheomag::diagnose::ringing_frequencies(residual, drive, dt);
  // Each generating frequency is one of the (at most kRingingStarts) returned.
  auto found = [&](double want) {
    return std::any_of(f.begin(), f.end(),
                       [want](double x) { return std::abs(x / want - 1.0) < 0.02; });
  };
  ASSERT_LE(f.size(), rheomag::diagnose::kRingingStarts);
  EXPECT_TRUE(found(f_ring)) << "the 61 Hz ring";
  EXPECT_TRUE(found(3.0 * f_drive)) << "the third drive harmonic";
  // Nothing above the band of a drive that is itself the whole signal.
  EXPECT_TRUE(rheomag::diagnose::ringing_frequencies(drive, drive, dt).empty() ||
              rheomag::diagnose::ringing_frequencies(drive, drive, dt).front() > 2.0 * f_drive);
}

// The bypass rig of paper 001 with the stated oil's compliance (2e-5 m^3 per chamber, 1.5 GPa:
// loop compliance C = 2e-5 / 1.5e9 / 2 = 6.67e-15 m^3/Pa) and an inertance I = 1e9 Pa s^2/m^3:
// f = 1 / (2 pi sqrt(I C)) = 61.6 Hz, quality factor sqrt(I / C) / R = 26 above yield. The
// diagnosis must name fluid_inertia with I within 20 % (the sidecar's map is 10 % off and
// calibrated; the fitted inertance trades a little with it), and only with the ringing start:
// from the decade grid alone the fit stays in another mode of the error.
TEST(DiagnoseRinging, RingingInertanceIsNamed) {
  auto truth = rheomag::test::bypass_rig();
  rheomag::lumped::ChamberBlock oil;
  oil.oil_volume = 2e-5;
  truth.compressibility = oil;
  truth.inertance = 1e9;
  const auto in = rheomag::test::drive(2.0, 1000.0,
                                       {"velocity=sine:amplitude=0.05,frequency=4",
                                        "current=steps:levels=0.3/0.6/0.2/0.5,period=0.5"});
  const auto v = rheomag::test::make_recording(truth, in, 2e4);
  const double c = rheomag::diagnose::loop_compliance(truth);
  EXPECT_NEAR(c, 2e-5 / 1.5e9 / 2.0, 1e-20);

  rheomag::diagnose::DiagnoseOptions options;
  const auto d = rheomag::diagnose::diagnose(v.noisy, options);
  rheomag::test::print_findings(d);
  ASSERT_FALSE(d.findings.empty());
  EXPECT_EQ(d.findings.front().effect->name(), "fluid_inertia");
  ASSERT_EQ(d.findings.front().params.size(), 1u);
  EXPECT_NEAR(d.findings.front().params.front() / 1e9, 1.0, 0.2);

  options.ringing_start = false;
  const auto grid_only = rheomag::diagnose::diagnose(v.noisy, options);
  rheomag::test::print_findings(grid_only);
  const bool named = !grid_only.findings.empty() &&
                     grid_only.findings.front().effect->name() == "fluid_inertia" &&
                     std::abs(grid_only.findings.front().params.front() / 1e9 - 1.0) < 0.2;
  EXPECT_FALSE(named) << "the decade grid alone finds this inertance: the test does not show "
                         "what the ringing start adds";
}

}  // namespace
