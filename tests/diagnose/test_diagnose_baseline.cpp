// What the baseline contains (issue 13): everything the sidecar states (a stated coil
// inductance is not named as missing), the recording's nuisances calibrated and reported but
// never named (a channel skew of a fraction of a sample, drives recorded as held samples, a
// smoother pre-yield than the Bingham map), and the FE chain of a [valve] case as the static map.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "core/error.hpp"
#include "diagnose/diagnose_run.hpp"
#include "test_diagnose_fixture.hpp"

namespace {

using rheomag::diagnose::Diagnosis;
using rheomag::lumped::DriverMode;
using rheomag::lumped::RigKind;
using rheomag::test::bypass_rig;
using rheomag::test::drive;
using rheomag::test::make_recording;

void print(const Diagnosis& d, double ceiling) {
  std::cout << rheomag::diagnose::diagnosis_json(d)["baseline"].dump(1) << "\nfinal FIT "
            << d.final_fit_percent << ", ceiling " << ceiling << "\n";
  for (const auto& f : d.findings) {
    std::cout << "  named " << f.effect->name();
    for (std::size_t j = 0; j < f.params.size(); ++j)
      std::cout << " " << f.param_names[j] << " " << f.params[j];
    std::cout << "\n";
  }
  for (const auto& n : d.notes) std::cout << "  note: " << n << "\n";
}

const std::vector<std::string> kPaper001 = {"displacement=sine:amplitude=0.025,frequency=1",
                                            "current=steps:levels=0/1/0.5,period=0.3"};

/// A recording whose output channel is read `skew` samples after its drive channels: the truth
/// is driven on the time base t - skew dt, and the drives are recorded on t.
rheomag::test::VirtualRecording skewed_recording(double duration, double rate,
                                                 const std::vector<std::string>& signals,
                                                 double skew) {
  rheomag::lumped::Recording early;
  for (double t : rheomag::lumped::uniform_times(duration, rate))
    early.t.push_back(t - skew / rate);
  for (const auto& s : signals) rheomag::lumped::add_signal(early, s);
  auto v = make_recording(bypass_rig(), early, 3e4);
  rheomag::lumped::Recording on_time;
  on_time.t = rheomag::lumped::uniform_times(duration, rate);
  for (const auto& s : signals) rheomag::lumped::add_signal(on_time, s);
  v.noisy.t = on_time.t;
  for (auto& [name, column] : on_time.columns)
    if (v.noisy.columns.count(name)) v.noisy.columns[name] = column;
  return v;
}

/// 1.6 s of the voltage-driven pump (250 Hz, voltage steps every 0.4 s) simulated from `truth`,
/// with `stated` [H] as the sidecar's [coil] inductance.
rheomag::test::VirtualRecording stated_coil_pump(rheomag::lumped::RigSpec truth, double stated) {
  truth.kind = RigKind::constant_velocity_pump;
  truth.driver_mode = DriverMode::voltage;
  truth.voltage_column = "voltage";
  auto v = make_recording(
      truth,
      drive(1.6, 250.0,
            {"velocity=constant:value=0.01", "voltage=steps:levels=0/8.9/4.45,period=0.4"}),
      3e4);
  v.noisy.meta.coil.inductance = stated;
  return v;
}

// A stated coil inductance (0.5 H on a voltage-driven pump coil, L/R = 56 ms) is part of the
// baseline: nothing is missing, and the report lists it.
TEST(DiagnoseBaseline, StatedInductanceIsNotMissing) {
  auto truth = bypass_rig();
  truth.coil.inductance = 0.5;
  const auto v = stated_coil_pump(truth, 0.5);  // the sidecar states it
  const auto d = rheomag::test::run_diagnosis(v.noisy);
  print(d, v.noise_ceiling);
  EXPECT_TRUE(d.findings.empty());
  const auto it = std::find_if(d.includes.begin(), d.includes.end(),
                               [](const auto& i) { return i.name == "coil_inductance"; });
  ASSERT_NE(it, d.includes.end());
  EXPECT_EQ(it->value, 0.5);
  EXPECT_NEAR(d.final_fit_percent, v.noise_ceiling, 2.0);
}

// A coil whose inductance is larger than the sidecar states (0.5 H against a stated 0.1 H;
// L/R 56 ms against 11 ms): the inductance beyond the stated one is named, coil_inductance with
// 0.4 H within 10 % (reference: the truth's 0.5 - 0.1 H), and the final FIT within 2 points of
// the noise ceiling. The stated coil's lag and a field lag behind it would be two lags in series;
// one lag of the summed inductance is what the truth has.
TEST(DiagnoseBaseline, AnInductanceBeyondTheStatedOneIsNamed) {
  auto truth = bypass_rig();
  truth.coil.inductance = 0.5;
  const auto v = stated_coil_pump(truth, 0.1);
  const auto d = rheomag::test::run_diagnosis(v.noisy);
  print(d, v.noise_ceiling);
  ASSERT_EQ(d.findings.size(), 1u);
  EXPECT_EQ(d.findings.front().effect->name(), "coil_inductance");
  EXPECT_NEAR(d.findings.front().params.at(0), 0.4, 0.04);
  EXPECT_NEAR(d.final_fit_percent, v.noise_ceiling, 2.0);
}

// The converse: the stated inductance is right (0.1 H) and a 40 ms MR response lags the field
// behind it. A field lag is named (mr_response_time, or eddy_currents, its twin), not an
// inductance beyond the stated one, and the lag within 15 % of the truth's 40 ms.
TEST(DiagnoseBaseline, AFieldLagBehindAStatedCoilIsNotAnInductance) {
  auto truth = bypass_rig();
  truth.coil.inductance = 0.1;
  truth.mr_response_time = 0.04;
  const auto v = stated_coil_pump(truth, 0.1);
  const auto d = rheomag::test::run_diagnosis(v.noisy);
  print(d, v.noise_ceiling);
  ASSERT_EQ(d.findings.size(), 1u);
  const std::string named = d.findings.front().effect->name();
  EXPECT_TRUE(named == "mr_response_time" || named == "eddy_currents") << named;
  EXPECT_NEAR(d.findings.front().params.at(0), 0.04, 0.006);
}

// The output channel read 0.8 samples after the drive channels (2.7 ms at 300 Hz): a clean
// recording still names nothing (without the delay nuisance a ~2 ms field lag was named), and
// the delay is calibrated to 0.8 +- 0.2 samples.
TEST(DiagnoseBaseline, ChannelSkewIsANuisance) {
  const auto v = skewed_recording(1.5, 300.0, kPaper001, 0.8);
  const auto d = rheomag::test::run_diagnosis(v.noisy);
  print(d, v.noise_ceiling);
  EXPECT_TRUE(d.findings.empty());
  EXPECT_NEAR(d.nuisance.delay_samples, 0.8, 0.2);
  // Achievable: the truth driven by the recorded drives (a current step recorded on the drive's
  // sample grid cannot be placed within the sample by any model).
  const double achievable = rheomag::lumped::fit_percent(
      v.noisy.column("pressure"),
      rheomag::lumped::simulate_rig(bypass_rig(), v.noisy).column("pressure"));
  std::cout << "achievable ceiling " << achievable << "\n";
  EXPECT_GT(d.final_fit_percent, achievable - 2.0);
}

// The output delay each candidate is screened with (issue 13, session 5): the baseline's own
// output shifted by 0.7 samples is the "measurement"; the scan in tenths of a sample and the
// parabola through the best three recover the shift to 3 % of a sample (linear interpolation
// of an already interpolated signal is the only error) and leave no error beyond 1e-4 of the
// signal's energy.
TEST(DiagnoseBaseline, BestDelayRecoversASubSampleShift) {
  const auto v = make_recording(bypass_rig(), drive(1.5, 300.0, {kPaper001[0], kPaper001[1]}), 0);
  const rheomag::diagnose::DiagnosisModel model(v.noisy);
  auto values = std::vector<double>();
  for (const auto& p : model.static_params()) values.push_back(p.nominal);
  values[model.delay_index()] = 0.0;
  const auto undelayed = model.predict({}, values);
  auto shifted = values;
  shifted[model.delay_index()] = 0.7 * model.sample_interval();
  auto rec = v.noisy;
  rec.columns.at("pressure") = model.delayed(undelayed, shifted);
  const rheomag::diagnose::DiagnosisModel target(rec);
  double sse = -1.0;
  const double delay = target.best_delay(undelayed, values, sse);
  EXPECT_NEAR(delay / model.sample_interval(), 0.7, 0.03);
  double energy = 0.0;
  for (double y : undelayed) energy += y * y;
  EXPECT_LT(sse, 1e-4 * energy);
}

// The recorder's valve is smoother at pre-yield than the Bingham map: its plug switch is 2 % of
// the peak flow wide. Calibrated (within a factor 1.5), not named.
TEST(DiagnoseBaseline, PreYieldSmoothingIsANuisance) {
  auto truth = bypass_rig();
  const double peak_flow = truth.piston_area * 2 * M_PI * 0.025;
  truth.valve.regularisation_flow = 0.02 * peak_flow;
  const auto v = make_recording(truth, drive(1.5, 300.0, {kPaper001[0], kPaper001[1]}), 3e4);
  const auto d = rheomag::test::run_diagnosis(v.noisy);
  print(d, v.noise_ceiling);
  EXPECT_TRUE(d.findings.empty());
  EXPECT_GT(d.nuisance.preyield_fraction, 0.02 / 1.5);
  EXPECT_LT(d.nuisance.preyield_fraction, 0.02 * 1.5);
  EXPECT_NEAR(d.final_fit_percent, v.noise_ceiling, 2.0);
}

// FE-chain proof: a recording simulated through the fluid chain of cases/annular_valve.toml
// (yield 20 % below the chain, viscous 10 % above) with a concealed 20 ms MR response time,
// diagnosed with the same [valve] case as its baseline: the lag is named and recovered within
// 20 %, the yield scale within 5 % (the viscous scale is weakly identified at this noise: the
// final FIT reaches the noise ceiling with it anywhere in 0.85-1.1).
TEST(DiagnoseBaseline, FeChainBaselineNamesAConcealedLag) {
  auto truth = bypass_rig();
  truth.valve.yield_current.clear();
  truth.valve.yield_pressure.clear();
  truth.valve.case_file = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";
  truth.valve.yield_scale = 0.8;
  truth.valve.viscous_scale = 1.1;
  truth.valve.regularisation_flow = 1e-3 * truth.piston_area * 0.1;
  truth.mr_response_time = 0.02;
  const auto v = make_recording(truth, drive(1.5, 300.0, {kPaper001[0], kPaper001[1]}), 3e4);
  ASSERT_FALSE(v.noisy.meta.valve.case_file.empty());
  const auto d = rheomag::test::run_diagnosis(v.noisy);
  print(d, v.noise_ceiling);
  ASSERT_FALSE(d.findings.empty());
  const auto& f = d.findings.front();
  EXPECT_TRUE(f.effect->name() == "mr_response_time" || f.effect->name() == "eddy_currents");
  EXPECT_NEAR(f.params.front() / 0.02, 1.0, 0.2);
  EXPECT_EQ(d.findings.size(), 1u);
  EXPECT_NEAR(d.final_fit.values[0] / 0.8, 1.0, 0.05);  // yield_scale
  EXPECT_NEAR(d.final_fit_percent, v.noise_ceiling, 2.0);
  const auto it = std::find_if(d.includes.begin(), d.includes.end(),
                               [](const auto& i) { return i.name == "static_map"; });
  ASSERT_NE(it, d.includes.end());
  EXPECT_NE(it->source.find("annular_valve.toml"), std::string::npos);
}

// A [valve] case that does not exist is bad input naming the key.
TEST(DiagnoseBaseline, MissingValveCaseIsNamed) {
  auto v = make_recording(bypass_rig(), drive(1.0, 200.0, {kPaper001[0], kPaper001[1]}), 3e4);
  v.noisy.meta.valve.yield_current.clear();
  v.noisy.meta.valve.yield_pressure.clear();
  v.noisy.meta.valve.case_file = "no_such_valve.toml";
  try {
    (void)rheomag::diagnose::diagnose(v.noisy);
    ADD_FAILURE() << "no InputError";
  } catch (const rheomag::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("[valve] case"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no_such_valve.toml"), std::string::npos) << e.what();
  }
}

}  // namespace

namespace {

/// A clean bypass recording at 300 Hz whose truth runs on a time base 8x finer: the coil current
/// acts as held samples (`held`: a DAC's zero-order hold, each sample standing for the interval
/// it begins, the piston's motion recorded as the mean over that interval, i.e. at its middle)
/// or linear between the recorder's samples (motion recorded at the sample's instant).
rheomag::test::VirtualRecording sampled_recording(bool held) {
  constexpr double kRate = 300.0, kDuration = 1.5;
  constexpr int kFine = 8;
  const auto coarse = drive(kDuration, kRate, {kPaper001[1]});
  const auto& tc = coarse.t;
  const auto& ic = coarse.columns.at("current");
  const double dt = 1.0 / kRate;
  rheomag::lumped::Recording fine;
  fine.t = rheomag::lumped::uniform_times(kDuration, kFine * kRate);
  rheomag::lumped::add_signal(fine, kPaper001[0]);
  auto& current = fine.columns["current"];
  for (double t : fine.t) {
    const auto k = std::min(static_cast<std::size_t>(std::floor(t / dt + 1e-9)), tc.size() - 1);
    const double w = k + 1 < tc.size() ? (t - tc[k]) / dt : 0.0;
    current.push_back(held || k + 1 >= tc.size() ? ic[k] : (1 - w) * ic[k] + w * ic[k + 1]);
  }
  auto v = make_recording(bypass_rig(), fine, 3e4);
  // What the recorder writes: every kFine-th output sample, the current as commanded, the
  // motion at the sample's instant (smooth) or at its interval's middle (held).
  rheomag::lumped::Recording motion;
  for (double t : tc) motion.t.push_back(held ? t + 0.5 * dt : t);
  rheomag::lumped::add_signal(motion, kPaper001[0]);
  for (auto& [name, column] : v.noisy.columns) {
    std::vector<double> recorded;
    for (std::size_t k = 0; k < tc.size(); ++k) recorded.push_back(column[k * kFine]);
    column = std::move(recorded);
  }
  v.noisy.t = tc;
  v.noisy.columns["current"] = ic;
  for (const char* c : {"velocity", "displacement"}) v.noisy.columns[c] = motion.columns.at(c);
  return v;
}

}  // namespace

// The drive sampling convention is a nuisance the baseline calibrates (issue 13, session 6): the
// same clean recording with its coil current held between samples is calibrated as held, with
// it linear between samples as linear; nothing is named in either, and the convention chosen
// fits better than the other by the stated FIT points (printed; held: the step of every current
// edge where a linear reading ramps over a sample).
TEST(DiagnoseBaseline, DriveSamplingConventionIsCalibrated) {
  for (const bool held : {true, false}) {
    const auto v = sampled_recording(held);
    const auto d = rheomag::test::run_diagnosis(v.noisy);
    print(d, v.noise_ceiling);
    std::cout << (held ? "held" : "smooth") << " recording: calibrated as "
              << rheomag::diagnose::kDriveSamplingNames.name(d.nuisance.drive_sampling)
              << ", baseline FIT gain over the other convention " << d.nuisance.sampling_fit_gain
              << " points\n";
    EXPECT_EQ(d.nuisance.drive_sampling, held ? rheomag::diagnose::DriveSampling::held
                                              : rheomag::diagnose::DriveSampling::linear);
    EXPECT_GT(d.nuisance.sampling_fit_gain, 0.0);
    EXPECT_TRUE(d.findings.empty());
    const auto json = rheomag::diagnose::diagnosis_json(d)["baseline"]["nuisance"];
    EXPECT_EQ(json["drive_sampling"], held ? "held" : "linear");
  }
}

namespace {

/// A clean damper (bypass map, 150 N gas force) at 25 mm / 1 Hz with current steps, whose
/// chambers hold `oil_volume` m^3 of oil each (1.5 GPa) when `compliant`, and a stiff fluid
/// otherwise; the sidecar states that volume either way.
rheomag::test::VirtualRecording damper_with_stated_oil(double oil_volume, bool compliant) {
  auto truth = bypass_rig();
  truth.kind = RigKind::damper;
  truth.gas_force = 150.0;
  if (compliant) {
    rheomag::lumped::ChamberBlock oil;
    oil.oil_volume = oil_volume;
    truth.compressibility = oil;
  }
  auto v = make_recording(truth,
                          drive(3.0, 500.0,
                                {"displacement=sine:amplitude=0.025,frequency=1",
                                 "current=steps:levels=0/1/0.5,period=1"}),
                          15.0);
  v.noisy.meta.rig.chamber_volume = oil_volume;
  return v;
}

/// Diagnoses `v` and checks that nothing is named, the FIT reaches the noise ceiling (within 2
/// points) and the report's chamber_volume entry says `how` the oil was treated.
void expect_nothing_named_and_oil(const rheomag::test::VirtualRecording& v,
                                  const std::string& how) {
  const auto d = rheomag::test::run_diagnosis(v.noisy);
  print(d, v.noise_ceiling);
  EXPECT_TRUE(d.findings.empty());
  EXPECT_NEAR(d.final_fit_percent, v.noise_ceiling, 2.0);
  const auto it = std::find_if(d.includes.begin(), d.includes.end(),
                               [](const auto& i) { return i.name == "chamber_volume"; });
  ASSERT_NE(it, d.includes.end());
  EXPECT_NE(it->source.find(how), std::string::npos) << it->source;
}

}  // namespace

// The stated chambers' oil is compliant, and at a flow reversal that shows although the viscous
// lag R C / 2 (0.1 ms) is a twentieth of a sample: before the plug yields the other way, the piston
// must compress the oil by C P (P = 5.8 MPa at 1 A, C = V / K: 2e-5 m^3 / 1.5 GPa), 0.17 mm of
// stroke, some 18 ms after the reversal at 1 Hz. The baseline is calibrated with and without it
// and keeps it; nothing is named, and the FIT reaches the noise ceiling (within 2 points).
// Without the reversal rule the stiff baseline leaves the force's lag at every reversal, and
// pre_yield or compressibility is named for physics the sidecar stated.
TEST(DiagnoseBaseline, StatedOilComplianceShowsAtReversals) {
  expect_nothing_named_and_oil(damper_with_stated_oil(2e-5, true), "oil compliance simulated");
}

// The same recording from a simulator that keeps the stated oil stiff: the calibration keeps
// the stiff fluid, and nothing is named either — with 2e-5 m^3 (the reversal's swing matters)
// and with 1e-4 m^3 per chamber (the viscous lag, 0.45 ms, is also a quarter of a sample; a
// baseline that always simulated it reached 77 % FIT and named fluid_inertia and friction).
TEST(DiagnoseBaseline, StiffOilIsKeptWhereItFitsBetter) {
  for (double volume : {2e-5, 1e-4}) {
    SCOPED_TRACE(volume);
    expect_nothing_named_and_oil(damper_with_stated_oil(volume, false),
                                 "stiff fluid fitted better");
  }
}
