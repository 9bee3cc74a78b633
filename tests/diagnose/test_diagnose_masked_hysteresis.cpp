// An effect that alone makes the fit worse at the first forward step: a magnetic hysteresis
// (Duhem field) beside a chamber compliance, under a measured current with 0.1 % noise. With
// the compliance not yet in the model, the Duhem candidate is fitted but raises BIC by more than
// the margin, so it was never tried again; it must be tried once more after the compliance is
// accepted and then be named (`worth_retrying` in diagnose/diagnose_selection.cpp,
// docs/diagnosis.md). The confusion proof's Duhem + air pairs missed this way (seed 2026 #12,
// seed 4242 #7 and #12) are found since.
// Reference: the truth the recording was simulated from (a damper of the fixture's map, 14.7 mm
// at 0.98 Hz, current steps 0/0.985/0.595/0.492 A held 0.21 s; air 5.04e-7 m^3 per chamber;
// Duhem a = 8.98 /A, d = 0.447, loop half width (1 - d)/a = 61.6 mA; 5 N output noise).
// Tolerances: 20 % on the air volume and on the loop's half width (the tolerance of
// DiagnoseHysteresis: a and d trade along the half width), 2 FIT points to the noise ceiling
// (issue 5's acceptance for the virtual rig). Measured 2026-12-04: air +2.7 %, half width
// -8.0 %, final FIT 97.90 % against a ceiling of 99.72 %. Before the rule, the compliance alone
// (final FIT 93.3 %).

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <random>

#include "diagnose/candidates/magnetic_hysteresis.hpp"
#include "diagnose/diagnose_run.hpp"
#include "test_diagnose_fixture.hpp"

namespace {

using rheomag::lumped::RigKind;

double param(const rheomag::diagnose::Finding& f, const std::string& name) {
  for (std::size_t j = 0; j < f.param_names.size(); ++j)
    if (f.param_names[j] == name) return f.params[j];
  ADD_FAILURE() << "no parameter " << name << " in " << f.effect->name();
  return 0.0;
}

TEST(DiagnoseMasked, HysteresisThatAloneMadeTheFitWorseIsTriedAgainOnceTheAirIsIn) {
  const double a = 8.98, d_duhem = 0.447, air = 5.04e-7;
  auto truth = rheomag::test::bypass_rig();
  truth.kind = RigKind::damper;
  rheomag::lumped::ChamberBlock chamber;
  chamber.oil_volume = 2e-5;
  chamber.air_volume = air;
  truth.compressibility = chamber;
  truth.magnetic_hysteresis = rheomag::diagnose::duhem_field(a, d_duhem);
  auto v = rheomag::test::make_recording(
      truth,
      rheomag::test::drive(2.4, 250.0,
                           {"displacement=sine:amplitude=0.0147,frequency=0.984",
                            "current=steps:levels=0/0.985/0.595/0.492,period=0.21"}),
      5.0);
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.001);  // 0.1 % of the 1 A range
  for (double& i : v.noisy.columns.at("current")) i += noise(rng);
  const auto d = rheomag::test::run_diagnosis(v.noisy);
  rheomag::test::print_selection(d, v.noise_ceiling);

  // The masking happened: at step 1 the Duhem was fitted, not screened out, and made BIC worse
  // by more than the margin (10).
  const auto step1 = std::find_if(d.candidates.begin(), d.candidates.end(), [](const auto& s) {
    return s.step == 0 && s.effect->name() == "magnetic_hysteresis";
  });
  ASSERT_NE(step1, d.candidates.end());
  EXPECT_FALSE(step1->screened);
  EXPECT_LT(step1->delta_bic, -10.0);
  // Both named, the compliance first, nothing else.
  ASSERT_EQ(d.findings.size(), 2u);
  EXPECT_EQ(d.findings[0].effect->name(), "compressibility");
  EXPECT_EQ(d.findings[1].effect->name(), "magnetic_hysteresis");
  EXPECT_NEAR(d.findings[0].params[0] / air, 1.0, 0.2);
  const double half_width = (1.0 - param(d.findings[1], "d")) / param(d.findings[1], "a");
  EXPECT_NEAR(half_width / ((1.0 - d_duhem) / a), 1.0, 0.2);
  EXPECT_NEAR(d.final_fit_percent, v.noise_ceiling, 2.0);
}

}  // namespace
