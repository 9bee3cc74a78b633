// A fitted model as the diagnosis baseline ("my model from last month's tests against today's
// recording"): a grey-box Bingham model is fitted to a clean recording of the virtual bypass rig,
// written as its fitted-model JSON and read back; a later recording of the same rig with a
// concealed field lag is diagnosed with that model as the baseline. Acceptance: the lag is named
// (either field-lag name: they are one block) with its time constant within 20 % of the truth and
// nothing else is named; the same recording without the lag names nothing; a model of another rig
// or with other drive columns is refused naming the file and key.

#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "core/error.hpp"
#include "diagnose/diagnose_run.hpp"
#include "lumped/fit_model_json.hpp"
#include "lumped/greybox.hpp"
#include "test_diagnose_fixture.hpp"

namespace {

using rheomag::diagnose::DiagnoseOptions;
using rheomag::diagnose::Effect;
using rheomag::diagnose::effect_name;
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
  const auto fit = rheomag::lumped::fit_greybox(v.noisy, "bingham");
  const std::string text = rheomag::lumped::fit_model_json(fit, v.noisy.meta).dump();
  return {rheomag::lumped::parse_fit_model_json(text, "model.json"), "model.json"};
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
  return rheomag::diagnose::diagnose(rec, options);
}

TEST(DiagnoseFittedBaseline, NamesAFieldLagTheModelLacks) {
  const auto model = last_months_model();
  const auto d = diagnose_with(todays_recording(0.03), model);
  std::cout << "baseline FIT " << d.baseline_fit_percent << " %, final " << d.final_fit_percent
            << " %\n";
  for (const auto& f : d.findings)
    std::cout << "  " << effect_name(f.effect) << " " << f.params.front() << "\n";
  ASSERT_EQ(d.findings.size(), 1u);
  const auto& f = d.findings.front();
  EXPECT_TRUE(f.effect == Effect::mr_response_time || f.effect == Effect::eddy_currents)
      << effect_name(f.effect);
  EXPECT_NEAR(f.params.front() / 0.03, 1.0, 0.2);
  EXPECT_GT(d.final_fit_percent, d.baseline_fit_percent + 5.0);
  // baseline.includes lists the model and its held parameters.
  bool has_model = false;
  for (const auto& item : d.includes) has_model |= item.name == "fitted_model";
  EXPECT_TRUE(has_model);
  EXPECT_EQ(d.baseline.layout.front().name, "output_scale");
}

TEST(DiagnoseFittedBaseline, NamesNothingWhenTheDeviceIsUnchanged) {
  const auto d = diagnose_with(todays_recording(0.0), last_months_model());
  EXPECT_TRUE(d.findings.empty()) << effect_name(d.findings.front().effect);
  EXPECT_GT(d.final_fit_percent, 90.0);
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
