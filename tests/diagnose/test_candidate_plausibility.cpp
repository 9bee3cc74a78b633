// Parameters a candidate rules out itself (Candidate::implausible; docs/diagnosis.md, "Practical
// significance", test 5), checked at acceptance and again in the final joint re-fit: a Duhem loop
// pinned at the top of its reversible range, and a fluid heating whose heat store fills and
// empties within one flow cycle. Reference: the rules' stated thresholds (d within 0.01 of 0.98;
// tau below one flow cycle, here 1/0.8 Hz = 1.25 s from the velocity's reversals).

#include <gtest/gtest.h>

#include <string>

#include "diagnose/candidate.hpp"
#include "diagnose/candidate_registry.hpp"
#include "diagnose/diagnose_fit.hpp"
#include "diagnose/diagnose_model.hpp"
#include "test_diagnose_fixture.hpp"

namespace {

using rheomag::diagnose::Candidate;
using rheomag::diagnose::candidate_named;
using rheomag::diagnose::DiagnosisModel;
using rheomag::diagnose::ModelFit;

/// A 5 s bypass recording: a 0.8 Hz stroke (four flow cycles) under current steps.
DiagnosisModel bypass_model() {
  const auto in = rheomag::test::drive(
      5.0, 500.0,
      {"displacement=sine:amplitude=0.02,frequency=0.8", "current=steps:levels=0/1/0.5,period=1"});
  return DiagnosisModel(rheomag::test::make_recording(rheomag::test::bypass_rig(), in, 2e4).noisy);
}

/// A fit of `effect` alone at its nominal parameters with its last ones set to `tail`.
ModelFit fit_of(const DiagnosisModel& model, const Candidate& effect, std::vector<double> tail) {
  ModelFit fit;
  fit.effects = {&effect};
  fit.layout = model.layout(fit.effects);
  for (const auto& p : fit.layout) fit.values.push_back(p.nominal);
  std::copy(tail.begin(), tail.end(), fit.values.end() - static_cast<std::ptrdiff_t>(tail.size()));
  return fit;
}

}  // namespace

TEST(CandidatePlausibility, DuhemLoopAtTheTopOfItsReversibleRangeIsNoLoop) {
  const DiagnosisModel model = bypass_model();
  const Candidate& duhem = candidate_named("magnetic_hysteresis");
  const std::string pinned = duhem.implausible(model, fit_of(model, duhem, {2.0, 0.98}));
  EXPECT_NE(pinned.find("top of its range"), std::string::npos) << pinned;
  EXPECT_FALSE(duhem.implausible(model, fit_of(model, duhem, {2.0, 0.975})).empty());
  EXPECT_EQ(duhem.implausible(model, fit_of(model, duhem, {2.0, 0.965})), "");
  EXPECT_EQ(duhem.implausible(model, fit_of(model, duhem, {5.0, 0.5})), "");
}

TEST(CandidatePlausibility, FluidHeatingFasterThanAFlowCycleStoresNothing) {
  const DiagnosisModel model = bypass_model();
  const Candidate& heating = candidate_named("fluid_heating");
  const std::string fast = heating.implausible(model, fit_of(model, heating, {0.1, 1.0}));
  EXPECT_NE(fast.find("one flow cycle (1.25 s)"), std::string::npos) << fast;
  EXPECT_EQ(heating.implausible(model, fit_of(model, heating, {0.1, 1.5})), "");
  EXPECT_EQ(heating.implausible(model, fit_of(model, heating, {0.1, 20.0})), "");
}
