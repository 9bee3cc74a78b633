// The candidate registry: the eleven candidates, unique names, SI units on every parameter, and
// the trial order of each kind of baseline.

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "diagnose/candidate_registry.hpp"
#include "test_diagnose_fixture.hpp"

using rheomag::diagnose::applicable_candidates;
using rheomag::diagnose::Candidate;
using rheomag::diagnose::candidate_named;
using rheomag::diagnose::candidates_in_trial_order;
using rheomag::diagnose::DiagnosisModel;
using rheomag::diagnose::registered_candidates;

namespace {

std::vector<std::string> names(const std::vector<const Candidate*>& list) {
  std::vector<std::string> out;
  for (const Candidate* c : list) out.push_back(c->name());
  return out;
}

}  // namespace

TEST(CandidateRegistry, ListsTheElevenCandidatesWithUniqueNames) {
  const auto all = names(registered_candidates());
  EXPECT_EQ(all, (std::vector<std::string>{
                     "compressibility", "fluid_inertia", "magnetic_hysteresis", "eddy_currents",
                     "coil_inductance", "coil_heating", "mr_response_time", "friction", "pre_yield",
                     "fluid_heating", "gas_spring"}));
  EXPECT_EQ(std::set<std::string>(all.begin(), all.end()).size(), all.size());
  for (const auto& name : all) EXPECT_EQ(candidate_named(name).name(), name);
  EXPECT_THROW(candidate_named("no_such_effect"), std::exception);
}

TEST(CandidateRegistry, TrialOrderOfEachBaseline) {
  EXPECT_EQ(
      names(candidates_in_trial_order(false)),
      (std::vector<std::string>{"compressibility", "pre_yield", "fluid_inertia", "mr_response_time",
                                "eddy_currents", "magnetic_hysteresis", "coil_inductance",
                                "coil_heating", "friction", "fluid_heating", "gas_spring"}));
  // On a fitted model: the blocks on its inputs, then those on its output.
  EXPECT_EQ(
      names(candidates_in_trial_order(true)),
      (std::vector<std::string>{"mr_response_time", "eddy_currents", "magnetic_hysteresis",
                                "coil_inductance", "fluid_inertia", "friction", "gas_spring"}));
}

TEST(CandidateRegistry, EveryParameterHasAUnit) {
  // A bypass rig driven by a current with a reversing flow: every candidate's parameters can be
  // asked for (the applicable ones and the rest alike).
  const auto v = rheomag::test::make_recording(
      rheomag::test::bypass_rig(),
      rheomag::test::drive(1.0, 300.0,
                           {"displacement=sine:amplitude=0.025,frequency=1",
                            "current=steps:levels=0/0.5/1/0.5,period=0.3"}),
      3e4);
  const DiagnosisModel model(v.noisy);
  for (const Candidate* c : registered_candidates()) {
    const auto params = c->params(model);
    EXPECT_FALSE(params.empty()) << c->name();
    for (const auto& p : params) {
      EXPECT_FALSE(p.unit.empty()) << c->name() << " " << p.name;
      EXPECT_LE(p.lower, p.nominal) << c->name() << " " << p.name;
      EXPECT_LE(p.nominal, p.upper) << c->name() << " " << p.name;
    }
  }
  EXPECT_FALSE(applicable_candidates(model).empty());
}
