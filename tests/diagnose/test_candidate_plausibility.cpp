// Parameters a candidate rules out itself (Candidate::implausible; docs/diagnosis.md, "Practical
// significance", test 5), checked at acceptance and again in the final joint re-fit: a Duhem loop
// pinned at the top of its reversible range, a Duhem loop whose offset is a function of the
// current alone, and a fluid heating whose heat store fills and empties within one flow cycle.
// Reference: the rules' stated thresholds (d within 0.01 of 0.98; under 15 % of the loop's offset
// (rms) depending on the direction of approach, where a level reached from both directions gives
// about 80 % by the count of the levels below; tau below one flow cycle, here 1/0.8 Hz = 1.25 s
// from the velocity's reversals).

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

/// A 5 s bypass recording: a 0.8 Hz stroke (four flow cycles) under the coil current `current`
/// (a signal spec, lumped/signals.cpp).
DiagnosisModel bypass_model(const std::string& current = "steps:levels=0/1/0.5,period=1") {
  const auto in = rheomag::test::drive(
      5.0, 500.0, {"displacement=sine:amplitude=0.02,frequency=0.8", "current=" + current});
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

TEST(CandidatePlausibility, DuhemLoopWhoseLevelsAreEachReachedFromOneDirectionIsAReshapedMap) {
  // A narrow loop (half width (1 - d)/a = 0.013 A) under instantaneous current steps. Levels
  // 0.3 and 0.5 are reached from below and 0.2 from above, once each: the loop's offset at each
  // level is one number, which a yield map reshaped at those currents gives as well.
  const Candidate& duhem = candidate_named("magnetic_hysteresis");
  const std::vector<double> narrow_loop = {26.0, 0.66};
  const DiagnosisModel one_way = bypass_model("steps:levels=0.05/0.3/0.5/0.2,period=1.25");
  const std::string why = duhem.implausible(one_way, fit_of(one_way, duhem, narrow_loop));
  EXPECT_NE(why.find("depends on the direction of approach for only"), std::string::npos) << why;
  EXPECT_NE(why.find("half width (0.0131 A)"), std::string::npos) << why;
  // 0.3 reached from below and then from above: the offset changes sign with the approach.
  const DiagnosisModel both_ways = bypass_model("steps:levels=0.05/0.3/0.5/0.3,period=1.25");
  EXPECT_EQ(duhem.implausible(both_ways, fit_of(both_ways, duhem, narrow_loop)), "");
  // A sinusoidal current passes every level both ways.
  const DiagnosisModel sine = bypass_model("sine:amplitude=0.4,offset=0.5,frequency=0.8");
  EXPECT_EQ(duhem.implausible(sine, fit_of(sine, duhem, narrow_loop)), "");
}

TEST(CandidatePlausibility, FluidHeatingFasterThanAFlowCycleStoresNothing) {
  const DiagnosisModel model = bypass_model();
  const Candidate& heating = candidate_named("fluid_heating");
  const std::string fast = heating.implausible(model, fit_of(model, heating, {0.1, 1.0}));
  EXPECT_NE(fast.find("one flow cycle (1.25 s)"), std::string::npos) << fast;
  EXPECT_EQ(heating.implausible(model, fit_of(model, heating, {0.1, 1.5})), "");
  EXPECT_EQ(heating.implausible(model, fit_of(model, heating, {0.1, 20.0})), "");
}
