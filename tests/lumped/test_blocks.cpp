// Each lumped block against an analytic response: RL step, first-order lag, Maxwell relaxation,
// Duhem loop closing, LuGre steady state = Bingham, thermal steady state, PI tracking, eddy time
// constant; and convergence of the regularised sign/plug switches as their width shrinks.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "lumped/blocks.hpp"
#include "lumped/pheno_simulation.hpp"
#include "lumped/rig_model.hpp"
#include "lumped/signals.hpp"
#include "lumped/transfer_function.hpp"
#include "tests/lumped/bypass_rig.hpp"

using namespace rheomag::lumped;

namespace {

Recording drive_with(double duration, double rate, const std::vector<std::string>& signals) {
  Recording d;
  d.t = uniform_times(duration, rate);
  for (const auto& s : signals) add_signal(d, s);
  return d;
}

RigSpec coil_bench(DriverMode mode) {
  RigSpec s;
  s.kind = RigKind::coil_bench;
  s.driver_mode = mode;
  s.voltage_column = "voltage";
  s.coil.resistance_20c = 8.9;
  s.coil.inductance = 0.12;
  return s;
}

using rheomag::test::bypass_rig;

}  // namespace

// RL step (paper 002's u = iR + L di/dt with constant L): i(t) = V/R (1 - exp(-(t - t0) R / L)),
// t0 = middle of the one-sample ramp of the step. Tolerance 1e-3 V/R (integrator tol 1e-6).
TEST(Blocks, RLStepResponse) {
  RigSpec s = coil_bench(DriverMode::voltage);
  Recording d = drive_with(0.2, 1e4, {"voltage=steps:levels=0/12,period=0.05"});
  Recording r = simulate_rig(s, d);
  const double R = 8.9, L = 0.12, V = 12.0, t0 = 0.05 - 0.5e-4;
  const auto& i = r.column("current");
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    if (r.t[k] < 0.05 || r.t[k] >= 0.1) continue;
    const double exact = V / R * (1.0 - std::exp(-(r.t[k] - t0) * R / L));
    ASSERT_NEAR(i[k], exact, 1e-3 * V / R) << "t = " << r.t[k];
  }
}

// MR response lag (first-order): at constant flow, dp(t) - R Q = p_y(1 A) (1 - exp(-(t-t0)/tau))
// tanh(Q/Q_eps) after a current step 0 -> 1 A. Tolerance 1e-3 p_y.
TEST(Blocks, FirstOrderLagOfMrResponse) {
  RigSpec s = bypass_rig();
  s.mr_response_time = 0.02;
  Recording d = drive_with(
      0.2, 1e4, {"velocity=constant:value=0.01", "current=steps:levels=0/1,period=0.05"});
  Recording r = simulate_rig(s, d);
  const double Q = 0.01 * 4.524e-4, py = 5.8e6, t0 = 0.05 - 0.5e-4;
  const auto& p = r.column("pressure");
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    if (r.t[k] < 0.05 || r.t[k] >= 0.1) continue;
    const double exact =
        1.5e10 * Q + py * (1.0 - std::exp(-(r.t[k] - t0) / 0.02)) * std::tanh(Q / 1e-9);
    ASSERT_NEAR(p[k], exact, 1e-3 * py) << "t = " << r.t[k];
  }
}

// Maxwell (paper 004 eq. 8) after a velocity step 0 -> v: F = F_d(v) (1 - exp(-(t - t0)/zeta)).
// Tolerance 1e-3 F_d.
TEST(Blocks, MaxwellRelaxation) {
  Recording d = drive_with(0.2, 1e4,
                           {"velocity=steps:levels=0/0.1,period=0.05",
                            "displacement=constant:value=0", "current=constant:value=1"});
  d.columns["force"] = std::vector<double>(d.t.size(), 0.0);
  d.meta.drive = {"displacement", "velocity", "current"};
  d.meta.output = "force";
  GreyboxSetup setup = greybox_setup_for(d, PhenoKind::maxwell);
  // time_constant, viscous, field_force, field_force_per_field, shape, offset
  std::vector<double> p{0.016, 1200.0, 150.0, 600.0, 15.0, 0.0};
  std::vector<double> f = simulate_pheno(d, setup, p);
  const double fd = 1200.0 * 0.1 + 750.0 * std::tanh(1.5), t0 = 0.05 - 0.5e-4;
  for (std::size_t k = 0; k < d.t.size(); ++k) {
    if (d.t[k] < 0.05 || d.t[k] >= 0.1) continue;
    ASSERT_NEAR(f[k], fd * (1.0 - std::exp(-(d.t[k] - t0) / 0.016)), 1e-3 * fd);
  }
}

// LuGre valve model (paper 001 eqs. 8-9, exponent 1) at constant motion reaches the Bingham law
// dp = stiffness sign(Q) + viscous Q / motion_scale (z -> sign Q). Tolerance 1e-3 relative
// (regularisation width 1e-6 of the motion).
TEST(Blocks, LuGreSteadyStateIsBingham) {
  for (double v : {0.05, -0.03}) {
    Recording d = drive_with(1.0, 1e3,
                             {"velocity=constant:value=" + std::to_string(v),
                              "displacement=constant:value=0", "current=constant:value=0.5"});
    d.columns["force"] = std::vector<double>(d.t.size(), 0.0);
    d.meta.drive = {"displacement", "velocity", "current"};
    d.meta.output = "force";
    GreyboxSetup setup = greybox_setup_for(d, PhenoKind::lugre);
    setup.settings.motion_scale = 0.05;
    setup.settings.eps = 1e-8;
    // stiffness, stiffness_per_field, damping, rate, viscous, viscous_per_field, exponent, offset
    std::vector<double> p{100.0, 400.0, 0.2, 2000.0, 80.0, 40.0, 1.0, 0.0};
    const double y = simulate_pheno(d, setup, p).back();
    const double bingham =
        (100.0 + 400.0 * 0.5) * (v > 0 ? 1 : -1) + (80.0 + 40.0 * 0.5) * v / 0.05;
    EXPECT_NEAR(y, bingham, 1e-3 * std::abs(bingham)) << "v = " << v;
  }
}

// Duhem hysteresis (paper 004 eqs. 2-3) on a coil driven by a sine voltage: after the transient,
// the lambda-i loop closes (state one period later equal within 1e-3 of the flux swing), and its
// area is positive (it is a hysteresis loop, not a curve).
TEST(Blocks, DuhemLoopCloses) {
  RigSpec s = coil_bench(DriverMode::voltage);
  s.coil.inductance = 0.0;
  s.magnetic_hysteresis = DuhemBlock{2.0, 0.05, 0.5, 0.01, 0.035};
  Recording d = drive_with(6.0, 2e3, {"voltage=sine:amplitude=3,frequency=1"});
  Recording r = simulate_rig(s, d);
  const auto& i = r.column("current");
  const auto& lam = r.column("flux_linkage");
  const std::size_t period = 2000, n = r.t.size();
  double swing = 0.0, area = 0.0, drift = 0.0;
  for (std::size_t k = n - period; k < n; ++k) swing = std::max(swing, std::abs(lam[k]));
  for (std::size_t k = n - period; k < n; ++k) {
    drift = std::max(drift, std::abs(lam[k] - lam[k - period]));
    area += 0.5 * (lam[k] + lam[k - 1]) * (i[k] - i[k - 1]);
  }
  EXPECT_LT(drift, 1e-3 * swing);
  EXPECT_GT(std::abs(area), 1e-3 * swing * 3.0 / 8.9);
}

// Coil heating: constant 1 A, R(T) = R20 (1 + alpha (T - 20)); steady state
// dT = I^2 R20 Rth / (1 - alpha I^2 R20 Rth). After 20 time constants, within 0.05 K.
TEST(Blocks, CoilThermalSteadyState) {
  RigSpec s = coil_bench(DriverMode::current_source);
  s.coil_heating = ThermalBlock{2.0, 100.0, 20.0};
  Recording d = drive_with(2000.0, 5.0, {"current=constant:value=1"});
  Recording r = simulate_rig(s, d);
  const double k = 8.9 * 2.0, dT = k / (1.0 - kCopperAlpha * k);
  EXPECT_NEAR(r.column("temperature").back(), 20.0 + dT, 0.05);
}

// Fluid heating at a constant flow Q through a purely viscous valve (0 A, no yield), with no
// cooling to speak of (C = 10 J/K, tau 1e7 s: theta / R_th is 1e-5 of the heating): C dtheta/dt =
// R_v e^(-b theta) Q^2, so theta(t) = ln(1 + b k t) / b with k = R_th R_v Q^2 / tau. Tolerance 1e-4
// of the rise (integrator tol 1e-6); the pressure follows R_v e^(-b theta) Q to 1e-4.
TEST(Blocks, FluidHeatingThinsTheViscousPart) {
  RigSpec s = bypass_rig();
  s.kind = RigKind::constant_velocity_pump;
  FluidHeatingBlock heating;
  heating.thermal_resistance = 1e6;
  heating.thermal_time_constant = 1e7;
  heating.viscosity_slope = 0.02;
  s.fluid_heating = heating;
  const double velocity = 0.02;
  Recording d =
      drive_with(60.0, 10.0, {"velocity=constant:value=0.02", "current=constant:value=0"});
  Recording r = simulate_rig(s, d);
  const double q = s.piston_area * velocity, rv = s.valve.viscous_resistance;
  const double k = heating.thermal_resistance * rv * q * q / heating.thermal_time_constant;
  const auto& rise = r.column("fluid_temperature_rise");
  const auto& p = r.column("pressure");
  for (std::size_t j = 0; j < r.t.size(); j += 50) {
    const double exact = std::log1p(0.02 * k * r.t[j]) / 0.02;
    EXPECT_NEAR(rise[j], exact, 1e-4 * rise.back()) << "t = " << r.t[j];
    EXPECT_NEAR(p[j], rv * std::exp(-0.02 * exact) * q, 1e-4 * rv * q) << "t = " << r.t[j];
  }
  EXPECT_GT(rise.back(), 5.0);  // a rise that shows: the test checks the thinning, not noise
}

// Current-mode PI driver with a voltage limit tracks a current step (final error < 1e-4 A), and
// the limit holds (|u| <= V_max).
TEST(Blocks, PiDriverTracksCurrent) {
  RigSpec s = coil_bench(DriverMode::current_pi);
  s.driver.voltage_limit = 24.0;
  Recording d = drive_with(0.5, 1e4, {"current_cmd=steps:levels=0/1.5,period=0.25"});
  Recording r = simulate_rig(s, d);
  EXPECT_NEAR(r.column("current").back(), 1.5, 1e-4);
  for (double u : r.column("voltage")) ASSERT_LE(std::abs(u), 24.0 + 1e-9);
}

// Eddy time constant of a solid steel core: mu0 * 1000 * 5e6 S/m * (0.01 m)^2 / 2.405^2
// = 0.10864 s (hand computed).
TEST(Blocks, EddyTimeConstant) {
  EXPECT_NEAR(eddy_time_constant(1000.0, 5e6, 0.01), 0.10864, 1e-4);
}

// Incompressible limit: with a stiff chamber (bulk modulus 1e10 Pa, no air) and a Newtonian valve
// (0 A), the compliant rig's pressure equals the static map: the lag is R C = 30 us, so the rms
// difference must be within 0.5 % of the peak. (With a yield stress the plug must be compressed at
// each reversal, a real lag ~ sqrt(2 p_y C / dQ/dt) of several ms, so that case is not a limit.)
TEST(Blocks, StiffChamberGivesStaticMap) {
  RigSpec s = bypass_rig();
  s.valve.regularisation_flow = 1e-8;
  Recording d = drive_with(
      2.0, 1e3, {"displacement=sine:amplitude=0.025,frequency=0.7", "current=constant:value=0"});
  Recording ideal = simulate_rig(s, d);
  s.compressibility = ChamberBlock{2e-5, 1e10, 0.0, 1e5, 1.0};  // lag R C = 30 us
  Recording stiff = simulate_rig(s, d);
  double peak = 0.0, err = 0.0;
  for (std::size_t k = 1; k < d.t.size(); ++k) {  // sample 0: the chambers start at rest
    peak = std::max(peak, std::abs(ideal.column("pressure")[k]));
    const double e = ideal.column("pressure")[k] - stiff.column("pressure")[k];
    err += e * e / d.t.size();
  }
  EXPECT_LT(std::sqrt(err), 5e-3 * peak);
}

// Regularisation: the valve's smooth sign tanh(Q / Q_eps) converges to the exact Bingham law as
// Q_eps shrinks: the mean absolute deviation from the exact sign law falls at least 5x per decade.
TEST(Blocks, ValveRegularisationConverges) {
  Recording d = drive_with(
      2.0, 1e3, {"displacement=sine:amplitude=0.025,frequency=0.7", "current=constant:value=1"});
  std::vector<double> err;
  for (double qeps : {1e-6, 1e-7, 1e-8}) {
    RigSpec s = bypass_rig();
    s.valve.regularisation_flow = qeps;
    Recording r = simulate_rig(s, d);
    double e = 0.0;
    for (std::size_t k = 0; k < d.t.size(); ++k) {
      const double q = r.column("flow")[k];
      const double exact = 5.8e6 * ((q > 0) - (q < 0)) + 1.5e10 * q;
      e += std::abs(r.column("pressure")[k] - exact) / d.t.size();
    }
    err.push_back(e);
  }
  EXPECT_LT(err[1], err[0] / 5);
  EXPECT_LT(err[2], err[1] / 5);
}

// Bouc-Wen's smooth |.| (width eps): outputs converge as eps shrinks (error vs eps = 1e-9 m/s
// falls at least 5x per decade and is below 1e-3 of the force range at eps = 1e-6 m/s).
TEST(Blocks, BoucWenRegularisationConverges) {
  Recording d = drive_with(
      2.0, 2e3, {"displacement=sine:amplitude=0.01,frequency=2", "command=constant:value=1"});
  d.columns["force"] = std::vector<double>(d.t.size(), 0.0);
  d.meta.drive = {"displacement", "velocity", "command"};
  d.meta.output = "force";
  GreyboxSetup setup = greybox_setup_for(d, PhenoKind::bouc_wen);
  std::vector<double> p{14000.0, 69500.0, 2100.0, 350.0, 28300.0, 295.0, 4690.0,
                        500.0,   3.63e6,  3.63e6, 301.0, 190.0,   0.0};
  setup.settings.eps = 1e-9;
  std::vector<double> ref = simulate_pheno(d, setup, p);
  double range =
      *std::max_element(ref.begin(), ref.end()) - *std::min_element(ref.begin(), ref.end());
  std::vector<double> err;
  for (double eps : {1e-4, 1e-5, 1e-6}) {
    setup.settings.eps = eps;
    std::vector<double> y = simulate_pheno(d, setup, p);
    double e = 0.0;
    for (std::size_t k = 0; k < y.size(); ++k) e = std::max(e, std::abs(y[k] - ref[k]));
    err.push_back(e);
  }
  EXPECT_LT(err[1], err[0] / 5);
  EXPECT_LT(err[2], err[1] / 5);
  EXPECT_LT(err[2], 1e-3 * range);
}

// Transfer-function simulator against the analytic step response of a 2nd-order system
// (wn = 10 rad/s, zeta = 0.5): y = 1 - exp(-zeta wn t) sin(wd t + acos zeta) / sqrt(1 - zeta^2).
// Tolerance 1e-5. And TF14's gain n/O transcribed from paper 000 Table 7: 7.485 bar/A (the paper
// measured 8.5 bar at 1 A).
TEST(Blocks, TransferFunctionStepAndTf14Gain) {
  const double wn = 10.0, zeta = 0.5, wd = wn * std::sqrt(1 - zeta * zeta);
  TransferFunction tf{{wn * wn}, {1.0, 2 * zeta * wn, wn * wn}};
  Recording d = drive_with(2.0, 1e3, {"current=constant:value=1"});
  std::vector<double> y = simulate_transfer_function(tf, d.t, d.column("current"));
  for (std::size_t k = 0; k < d.t.size(); ++k) {
    const double t = d.t[k];
    const double exact = 1.0 - std::exp(-zeta * wn * t) * std::sin(wd * t + std::acos(zeta)) /
                                   std::sqrt(1 - zeta * zeta);
    ASSERT_NEAR(y[k], exact, 1e-5) << "t = " << t;
  }
  EXPECT_NEAR(dc_gain(tf14_paper000()), 7.4849, 1e-3);
}

// The lumped layer solves no FE: a valve that names a case must arrive with its map tabulated
// (coupling::with_chain_map); a caller that forgets is told so instead of getting a silent table.
TEST(Blocks, ValveCaseWithoutTabulatedMapIsRefused) {
  RigSpec s = bypass_rig();
  s.valve.case_file = "cases/annular_valve.toml";
  Recording d = drive_with(0.01, 1e3, {"velocity=constant:value=0.01", "current=constant:value=1"});
  EXPECT_THAT([&] { simulate_rig(s, d); },
              ::testing::ThrowsMessage<rheomag::InputError>(::testing::HasSubstr(
                  "the valve names the FE case cases/annular_valve.toml but carries no tabulated "
                  "map (coupling::with_chain_map fills it)")));
}
