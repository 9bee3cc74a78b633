// Diagnosis of magnetic hysteresis (paper 004's Duhem operator, eqs. 2-3) concealed between the
// imposed coil current and the field of the bypass rig of paper 001. Acceptance (issue 5): the
// right effect named first; fitted parameters within 20 % of the truth; final FIT% within 2 points
// of the noise ceiling.

#include <gtest/gtest.h>

#include <iostream>

#include "diagnose/candidates/magnetic_hysteresis.hpp"
#include "diagnose/diagnose_run.hpp"
#include "test_diagnose_fixture.hpp"

namespace {

using rheomag::test::bypass_rig;
using rheomag::test::drive;
using rheomag::test::make_recording;

double param(const rheomag::diagnose::Finding& f, const std::string& name) {
  for (std::size_t j = 0; j < f.param_names.size(); ++j)
    if (f.param_names[j] == name) return f.params[j];
  ADD_FAILURE() << "no parameter " << name << " in " << f.effect->name();
  return 0.0;
}

// The level 0.5 A is reached from below and from above: with hysteresis the field (and the yield
// pressure) there differs by about the loop width, and it stays while the current rests, unlike
// a lag. Truth a = 4 /A, d = 0.3 (loop half width (1 - d)/a = 0.175 A, within paper 004's range
// once its flux is expressed in field-equivalent amperes).
TEST(DiagnoseHysteresis, DuhemFieldIsMagneticHysteresis) {
  auto truth = bypass_rig();
  truth.magnetic_hysteresis = rheomag::diagnose::duhem_field(4.0, 0.3);
  const auto v = make_recording(truth,
                                drive(2.4, 300.0,
                                      {"displacement=sine:amplitude=0.025,frequency=1",
                                       "current=steps:levels=0/0.5/1/0.5,period=0.3"}),
                                3e4);
  const auto d = rheomag::test::run_diagnosis(v.noisy);
  std::cout << rheomag::diagnose::diagnosis_json(d).dump(1) << "\nnoise ceiling " << v.noise_ceiling
            << "\n";
  ASSERT_FALSE(d.findings.empty());
  const auto& f = d.findings.front();
  EXPECT_EQ(f.effect->name(), "magnetic_hysteresis");
  EXPECT_NEAR(param(f, "a") / 4.0, 1.0, 0.2);
  EXPECT_NEAR(param(f, "d") / 0.3, 1.0, 0.2);
  EXPECT_NEAR(d.final_fit_percent, v.noise_ceiling, 2.0);
}

// A field lag of the same size is not mistaken for hysteresis: with the same drive a slow MR
// response (25 ms) is named as a lag and magnetic_hysteresis is not named at all.
TEST(DiagnoseHysteresis, FieldLagIsNotHysteresis) {
  auto truth = bypass_rig();
  truth.mr_response_time = 0.025;
  const auto v = make_recording(truth,
                                drive(2.4, 300.0,
                                      {"displacement=sine:amplitude=0.025,frequency=1",
                                       "current=steps:levels=0/0.5/1/0.5,period=0.3"}),
                                3e4);
  const auto d = rheomag::test::run_diagnosis(v.noisy);
  ASSERT_FALSE(d.findings.empty());
  EXPECT_TRUE(d.findings.front().effect->name() == "mr_response_time" ||
              d.findings.front().effect->name() == "eddy_currents");
  for (const auto& f : d.findings) EXPECT_NE(f.effect->name(), "magnetic_hysteresis");
}

}  // namespace
