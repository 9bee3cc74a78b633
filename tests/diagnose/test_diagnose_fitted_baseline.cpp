// A fitted model as the diagnosis baseline ("my model from last month's tests against today's
// recording"): a grey-box Bingham model is fitted to a clean recording of the virtual bypass rig,
// written as its fitted-model JSON and read back; a later recording of the same rig with a
// concealed field lag is diagnosed with that model as the baseline. Acceptance: the lag is named
// (either field-lag name: they are one block) with its time constant within 20 % of the truth and
// nothing else is named; the same recording without the lag names nothing; a model of another rig
// or with other drive columns is refused naming the file and key.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <random>
#include <string>

#include "core/error.hpp"
#include "diagnose/diagnose_run.hpp"
#include "identify/fit_model_json.hpp"
#include "identify/greybox.hpp"
#include "identify/valve_chain_fit.hpp"
#include "test_diagnose_fixture.hpp"

namespace {

using rheomag::diagnose::DiagnoseOptions;
using rheomag::diagnose::ModelBaseline;
using rheomag::test::bypass_rig;
using rheomag::test::drive;
using rheomag::test::make_recording;

/// Last month's model: Bingham fitted to a clean-of-effects recording of the bypass rig, written
/// as JSON and read back (the round trip a user's file takes).
ModelBaseline last_months_model() {
  const auto v = make_recording(bypass_rig(),
                                drive(2.0, 300.0,
                                      {"displacement=sine:amplitude=0.025,frequency=1",
                                       "current=steps:levels=0/1,period=0.35"}),
                                3e4, 11);
  const auto fit = rheomag::identify::fit_greybox(v.noisy, "bingham");
  const std::string text = rheomag::identify::fit_model_json(fit, v.noisy.meta).dump();
  return {rheomag::identify::parse_fit_model_json(text, "model.json"), "model.json"};
}

/// Today's recording of the same rig (another drive), with `lag` [s] of MR response time.
rheomag::lumped::Recording todays_recording(double lag) {
  auto truth = bypass_rig();
  if (lag > 0.0) truth.mr_response_time = lag;
  return make_recording(truth,
                        drive(1.5, 300.0,
                              {"displacement=sine:amplitude=0.02,frequency=1.3",
                               "current=steps:levels=0/1,period=0.25"}),
                        3e4, 5)
      .noisy;
}

rheomag::diagnose::Diagnosis diagnose_with(const rheomag::lumped::Recording& rec,
                                           const ModelBaseline& model) {
  DiagnoseOptions options;
  options.baseline_model = model;
  if (std::getenv("RHEOMAG_DIAGNOSE_TRACE"))
    options.progress = [](const rheomag::ProgressEvent& e) {
      std::cerr << "diagnose: " << e.stage << " " << e.detail << "\n";
    };
  return rheomag::diagnose::diagnose(rec, options);
}

/// Prints the diagnosis and checks that it named exactly one field lag (either name: one
/// block) with a time constant within 20 % of `tau`.
void expect_one_field_lag(const rheomag::diagnose::Diagnosis& d, double tau) {
  std::cout << "baseline FIT " << d.baseline_fit_percent << " %, final " << d.final_fit_percent
            << " %\n";
  for (const auto& f : d.findings)
    std::cout << "  " << f.effect->name() << " " << f.params.front() << "\n";
  ASSERT_EQ(d.findings.size(), 1u);
  const auto& f = d.findings.front();
  EXPECT_TRUE(f.effect->name() == "mr_response_time" || f.effect->name() == "eddy_currents")
      << f.effect->name();
  EXPECT_NEAR(f.params.front() / tau, 1.0, 0.2);
}

TEST(DiagnoseFittedBaseline, NamesAFieldLagTheModelLacks) {
  const auto model = last_months_model();
  const auto d = diagnose_with(todays_recording(0.03), model);
  expect_one_field_lag(d, 0.03);
  EXPECT_GT(d.final_fit_percent, d.baseline_fit_percent + 5.0);
  // baseline.includes lists the model and its held parameters.
  bool has_model = false;
  for (const auto& item : d.includes) has_model |= item.name == "fitted_model";
  EXPECT_TRUE(has_model);
  EXPECT_EQ(d.baseline.layout.front().name, "output_scale");
}

TEST(DiagnoseFittedBaseline, NamesNothingWhenTheDeviceIsUnchanged) {
  const auto d = diagnose_with(todays_recording(0.0), last_months_model());
  EXPECT_TRUE(d.findings.empty()) << d.findings.front().effect->name();
  EXPECT_GT(d.final_fit_percent, 90.0);
}

/// A valve-chain damper model over a small hand-made static map (as `fit --model valve-chain`
/// stores it; no FE solve needed): yield 0.2-0.9 MPa over 0-1 A, piston 1e-3 m^2, 10 ms field lag.
rheomag::identify::ValveChainFit chain_damper_model() {
  auto map = std::make_shared<rheomag::lumped::ChainMapTable>();
  map->case_file = "valve.toml";
  map->current = {0.0, 0.5, 1.0};
  map->flow = {1e-7, 1e-6, 1e-5, 1e-4};
  map->yield = {2e5, 2.1e5, 2.2e5, 2.3e5, 5e5, 5.2e5, 5.4e5, 5.6e5, 8e5, 8.4e5, 8.7e5, 9e5};
  map->viscous_resistance = 2e9;
  rheomag::identify::ValveChainFit fit;
  fit.setup.map = map;
  fit.setup.motion_column = "velocity";
  fit.setup.field_column = "current";
  fit.setup.output_column = "force";
  fit.setup.piston_area = 1e-3;
  fit.setup.eps_flow = 1e-7;
  fit.params =
      rheomag::identify::valve_chain_parameters({1.0, 1.0, 0.01, 0.0}, /*compliant=*/false);
  return fit;
}

/// An empty recording of a damper with the valve-chain model's drives (velocity, current) and
/// piston, its force to be simulated; its columns are filled in by the caller.
rheomag::lumped::Recording chain_damper_recording() {
  rheomag::lumped::Recording rec;
  rec.csv_path = "damper.csv";
  rec.meta.sidecar_path = "damper.toml";
  rec.meta.drive = {"velocity", "current"};
  rec.meta.output = "force";
  rec.meta.rig.kind = rheomag::lumped::RigKind::damper;
  rec.meta.rig.piston_area = 1e-3;
  return rec;
}

/// The diagnosis of `rec` against the valve-chain model as its fitted baseline.
rheomag::diagnose::Diagnosis diagnose_against_chain(const rheomag::lumped::Recording& rec) {
  const auto model = rheomag::identify::parse_fit_model_json(
      rheomag::identify::fit_model_json(chain_damper_model(), rec.meta).dump(), "chain.json");
  const auto d = diagnose_with(rec, {model, "chain.json"});
  for (const auto& f : d.findings)
    std::cout << "  " << f.effect->name() << " " << f.params.front() << "\n";
  return d;
}

// The case literally: a recording simulated from a fitted (valve-chain) model plus a
// concealed effect - a 30 ms field lag in front of the model (the fluid or the core slower than
// when the model was fitted), 1 % force noise - is diagnosed with that model as its baseline:
// the lag named (either field-lag name), 30 ms within 20 %, nothing else. The truth's lag is
// integrated here independently (explicit Euler on 50 substeps per sample), not by the
// diagnosis's own exact discretisation.
TEST(DiagnoseFittedBaselineChain, NamesAFieldLagInFrontOfAValveChainModel) {
  const auto fit = chain_damper_model();
  auto rec = chain_damper_recording();
  const double dt = 0.002, tau = 0.03;
  std::vector<double> v, i, lagged;
  double state = 0.2;
  for (int k = 0; k < 1000; ++k) {
    const double t = k * dt;
    rec.t.push_back(t);
    v.push_back(0.05 * std::sin(2 * M_PI * 2 * t));
    i.push_back(static_cast<int>(t / 0.25) % 2 == 0 ? 0.2 : 0.9);
    if (k > 0)
      for (int s = 1; s <= 50; ++s) {
        const double u = i[k - 1] + (i[k] - i[k - 1]) * s / 50.0;
        state += dt / 50.0 * (u - state) / tau;
      }
    lagged.push_back(state);
  }
  rec.columns = {{"velocity", v}, {"current", lagged}, {"force", std::vector<double>(v.size())}};
  auto force = rheomag::identify::simulate_valve_chain(rec, fit);
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 10.0);  // ~1 % of the force's rms
  for (double& f : force) f += noise(rng);
  rec.columns["force"] = force;
  rec.columns["current"] = i;  // what the recorder saw: the coil current, not the field
  const auto d = diagnose_against_chain(rec);
  expect_one_field_lag(d, tau);
  bool has_map = false;
  for (const auto& item : d.includes) has_map |= item.name == "static_map";
  EXPECT_TRUE(has_map);
}

/// A recording of the valve-chain model at 2 Hz (50 mm/s) with the current switching between
/// 0.2 and 0.9 A every `half_period` [s], plus an exact Coulomb step of `friction` [N] (sign(v),
/// not the diagnosis's tanh) and 10 N of force noise.
rheomag::lumped::Recording chain_recording_with_friction(double half_period, double friction) {
  auto rec = chain_damper_recording();
  std::vector<double> v, i;
  for (int k = 0; k < 1000; ++k) {
    const double t = k * 0.002;
    rec.t.push_back(t);
    v.push_back(0.05 * std::sin(2 * M_PI * 2 * t));
    i.push_back(static_cast<int>(t / half_period) % 2 == 0 ? 0.2 : 0.9);
  }
  rec.columns = {{"velocity", v}, {"current", i}, {"force", std::vector<double>(v.size())}};
  auto force = rheomag::identify::simulate_valve_chain(rec, chain_damper_model());
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 10.0);
  for (std::size_t k = 0; k < force.size(); ++k)
    force[k] += friction * ((v[k] > 0.0) - (v[k] < 0.0)) + noise(rng);
  rec.columns["force"] = force;
  return rec;
}

// A Coulomb friction of 60 N (7 % of the force's rms) under a current that switches out of step
// with the velocity: named alone, within 10 % (measured 59.3 N, 2026-12-06).
TEST(DiagnoseFittedBaselineChain, NamesAFrictionAloneOnAValveChainModel) {
  const auto d = diagnose_against_chain(chain_recording_with_friction(0.175, 60.0));
  ASSERT_EQ(d.findings.size(), 1u);
  EXPECT_EQ(d.findings.front().effect->name(), "friction");
  EXPECT_NEAR(d.findings.front().params.front() / 60.0, 1.0, 0.1);
}

// The same friction when the current switches with the velocity's sign (0.2 A in extension,
// 0.9 A in compression): the step is then exactly a change of the calibrated output scale and
// offset (s Y_low + o = Y_low + F, -s Y_high + o = -Y_high - F), so no recording of this drive
// can tell it from a drift of the level. Nothing is named (measured: friction 14 N, 0.40 noise
// standard deviations; magnetic hysteresis 0.29; both under the 0.5 bar), in particular not the
// small magnetic hysteresis docs/diagnosis.md once listed as a known miss beside a friction.
TEST(DiagnoseFittedBaselineChain, NamesNothingFalseWhenTheCurrentFlipsWithTheVelocity) {
  const auto d = diagnose_against_chain(chain_recording_with_friction(0.25, 60.0));
  for (const auto& f : d.findings) ADD_FAILURE() << f.effect->name() << " named";
}

TEST(DiagnoseFittedBaseline, RefusesAModelOfAnotherRigKind) {
  const auto model = last_months_model();
  auto rec = todays_recording(0.0);
  rec.meta.rig.kind = rheomag::lumped::RigKind::damper;
  rec.meta.output = "force";
  try {
    diagnose_with(rec, model);
    FAIL() << "a bypass-cylinder model was accepted for a damper recording";
  } catch (const rheomag::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("model.json: key 'rig'"), std::string::npos) << what;
    EXPECT_NE(what.find("damper"), std::string::npos) << what;
  }
}

TEST(DiagnoseFittedBaseline, RefusesAModelWithOtherDriveColumns) {
  const auto model = last_months_model();
  auto rec = todays_recording(0.0);
  rec.columns["voltage"] = rec.column("current");
  rec.meta.drive = {"velocity", "voltage"};
  try {
    diagnose_with(rec, model);
    FAIL() << "a model fitted with a current drive was accepted for a voltage drive";
  } catch (const rheomag::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("model.json: key 'drive'"), std::string::npos) << what;
    EXPECT_NE(what.find("voltage"), std::string::npos) << what;
  }
}

}  // namespace
