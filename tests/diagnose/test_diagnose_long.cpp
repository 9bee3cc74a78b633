// The cost rule for long recordings (issue 13, session 6): with more samples than
// DiagnoseOptions::selection_samples, candidates are screened, fitted and checked on the
// consecutive stretch with the largest baseline residual energy, and only the final joint re-fit
// uses every sample. Reference: the same diagnosis on the whole recording (rule off). Tolerance:
// the same effects named; each parameter within 5 % of the whole-record value (and within 20 %
// of the truth, the acceptance of test_diagnose_rigs); the final FIT within 0.2 points of the
// whole-record FIT (both are the joint re-fit on every sample from nearby starts).

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

#include "diagnose/diagnose_run.hpp"
#include "test_diagnose_fixture.hpp"

namespace {

using rheomag::diagnose::DiagnoseOptions;
using rheomag::diagnose::Diagnosis;
using rheomag::lumped::RigKind;
using rheomag::test::bypass_rig;
using rheomag::test::drive;
using rheomag::test::make_recording;

void print(const char* what, const Diagnosis& d) {
  std::cout << what << ": baseline FIT " << d.baseline_fit_percent << ", final "
            << d.final_fit_percent << ", selection " << d.selection.begin << ":" << d.selection.end
            << "\n";
  rheomag::test::print_findings(d);
}

/// The field lags are one block: either name counts for the other.
std::string lag_as_one(const rheomag::diagnose::Candidate* e) {
  return e->name() == "eddy_currents" ? "mr_response_time" : e->name();
}

// A 6 s damper recording (1800 samples at 300 Hz) with friction 150 N and a 30 ms field lag,
// diagnosed whole and with the selection on 600 samples (2 of its 6 cycles).
TEST(DiagnoseLong, ExcerptSelectionNamesWhatTheWholeRecordNames) {
  auto truth = bypass_rig();
  truth.kind = RigKind::damper;
  truth.coulomb_force = 150.0;
  truth.mr_response_time = 0.03;
  const auto v = make_recording(truth,
                                drive(6.0, 300.0,
                                      {"displacement=sine:amplitude=0.025,frequency=1",
                                       "current=steps:levels=0/1/0.5,period=0.3"}),
                                15.0);
  DiagnoseOptions whole_options;
  whole_options.selection_samples = 0;
  const auto whole = rheomag::diagnose::diagnose(v.noisy, whole_options);
  print("whole record", whole);
  DiagnoseOptions part_options;
  part_options.selection_samples = 600;
  const auto part = rheomag::diagnose::diagnose(v.noisy, part_options);
  print("excerpt rule", part);

  EXPECT_EQ(whole.selection.size(), 0u);
  EXPECT_EQ(part.selection.size(), 600u);
  ASSERT_EQ(whole.findings.size(), 2u);
  ASSERT_EQ(part.findings.size(), whole.findings.size());
  for (std::size_t i = 0; i < whole.findings.size(); ++i) {
    const auto& w = whole.findings[i];
    const auto it = std::find_if(part.findings.begin(), part.findings.end(), [&](const auto& f) {
      return lag_as_one(f.effect) == lag_as_one(w.effect);
    });
    ASSERT_NE(it, part.findings.end()) << w.effect->name() << " not named on the excerpt";
    ASSERT_EQ(it->params.size(), w.params.size());
    for (std::size_t j = 0; j < w.params.size(); ++j)
      EXPECT_NEAR(it->params[j] / w.params[j], 1.0, 0.05) << w.param_names[j];
    const double truth_value = lag_as_one(w.effect) == "friction" ? 150.0 : 0.03;
    EXPECT_NEAR(it->params.front() / truth_value, 1.0, 0.2) << w.effect->name();
  }
  EXPECT_NEAR(part.final_fit_percent, whole.final_fit_percent, 0.2);
  EXPECT_NEAR(part.final_fit_percent, v.noise_ceiling, 2.0);
}

// The stretch chosen is where the baseline misses most: a recording whose last two thirds rest
// (piston still, current off) is diagnosed on its moving first third.
TEST(DiagnoseLong, ExcerptAvoidsTheRigAtRest) {
  auto truth = bypass_rig();
  truth.kind = RigKind::damper;
  truth.mr_response_time = 0.03;
  auto in = drive(
      6.0, 300.0,
      {"displacement=sine:amplitude=0.025,frequency=1", "current=steps:levels=0/1/0.5,period=0.3"});
  const std::size_t moving = in.t.size() / 3;
  const double x_end = in.columns.at("displacement")[moving - 1];
  for (std::size_t k = moving; k < in.t.size(); ++k) {
    in.columns.at("displacement")[k] = x_end;
    in.columns.at("velocity")[k] = 0.0;
    in.columns.at("current")[k] = 0.0;
  }
  const auto v = make_recording(truth, in, 15.0);
  DiagnoseOptions options;
  options.selection_samples = 500;
  const auto d = rheomag::diagnose::diagnose(v.noisy, options);
  print("rest after a third", d);
  EXPECT_LE(d.selection.end, moving + 50);
  ASSERT_FALSE(d.findings.empty());
  EXPECT_EQ(lag_as_one(d.findings.front().effect), "mr_response_time");
}

}  // namespace
