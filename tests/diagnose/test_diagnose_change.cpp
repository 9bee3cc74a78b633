// The change between a reference recording's diagnosis and today's (diagnose/diagnose_change.hpp),
// on hand-made diagnoses whose sizes are known exactly. Reference: the rule itself: a named
// effect's size is its finding's, else its first-step signed size; the change is today's minus
// the reference's, exact to rounding; what is sized on one side only is listed, not differenced.
// The rule on real recordings: DiagnoseRealInjection.TheChangeFromAReferenceRecordingIsTheEffect.

#include <gtest/gtest.h>

#include "diagnose/candidate_registry.hpp"
#include "diagnose/diagnose_change.hpp"

namespace {

using namespace rheomag::diagnose;

/// A first-step score of `name` with a signed size (and, when given, a derived moving mass).
CandidateScore signed_score(const std::string& name, double size, double mass = 0.0) {
  CandidateScore c;
  c.effect = &candidate_named(name);
  c.step = 0;
  c.param_names = {"size"};
  c.param_units = {"N"};
  c.signed_params = {size};
  if (mass != 0.0) c.signed_derived = {{"moving_mass", mass, "kg"}};
  return c;
}

/// A finding of `name` of size `size` (its final joint re-fit).
Finding named(const std::string& name, double size) {
  Finding f{};
  f.effect = &candidate_named(name);
  f.params = {size};
  return f;
}

TEST(DiagnoseChange, NamedSizesWinOverSignedOnesAndOneSidedEffectsAreListed) {
  Diagnosis today, before;
  today.candidates = {signed_score("friction", 30.0), signed_score("fluid_inertia", 2e6, 2.0),
                      signed_score("gas_spring", 100.0)};
  today.findings = {named("friction", 40.0)};
  before.recording = "before.csv";
  before.baseline_fit_percent = 95.5;
  before.candidates = {signed_score("friction", -5.0), signed_score("fluid_inertia", 5e5, 0.5)};
  Finding heavy = named("fluid_inertia", 1e6);
  heavy.derived = {{"moving_mass", 1.0, "kg"}};
  before.findings = {heavy};
  // A later step's score is not a first-step size.
  CandidateScore later = signed_score("gas_spring", 7.0);
  later.step = 1;
  before.candidates.push_back(later);

  const ReferenceComparison r = compare_with_reference(today, before);
  EXPECT_EQ(r.recording, "before.csv");
  EXPECT_DOUBLE_EQ(r.baseline_fit_percent, 95.5);
  ASSERT_EQ(r.findings, std::vector<std::string>{"fluid_inertia"});
  ASSERT_EQ(r.changes.size(), 2u);
  const EffectChange& f = r.changes[0];
  EXPECT_EQ(f.effect->name(), "friction");
  EXPECT_TRUE(f.named_today);
  EXPECT_FALSE(f.named_reference);
  EXPECT_DOUBLE_EQ(f.today, 40.0);
  EXPECT_DOUBLE_EQ(f.reference, -5.0);
  EXPECT_DOUBLE_EQ(f.change, 45.0);
  const EffectChange& m = r.changes[1];
  EXPECT_EQ(m.effect->name(), "fluid_inertia");
  EXPECT_FALSE(m.named_today);
  EXPECT_TRUE(m.named_reference);
  EXPECT_DOUBLE_EQ(m.change, 1e6);
  ASSERT_EQ(m.derived_change.size(), 1u);
  EXPECT_EQ(m.derived_change[0].name, "moving_mass");
  EXPECT_DOUBLE_EQ(m.derived_change[0].value, 1.0);
  EXPECT_EQ(r.sized_on_one, std::vector<std::string>{"gas_spring"});
  EXPECT_EQ(change_text(f),
            "friction: size 40.0 N today (named), -5.00 N in the reference (signed) -> change "
            "+45.0 N");

  // The other way round, every change changes sign.
  const ReferenceComparison back = compare_with_reference(before, today);
  ASSERT_EQ(back.changes.size(), 2u);
  EXPECT_DOUBLE_EQ(back.changes[0].change, -45.0);
  EXPECT_DOUBLE_EQ(back.changes[1].derived_change[0].value, -1.0);
  EXPECT_EQ(back.sized_on_one, std::vector<std::string>{"gas_spring"});
}

}  // namespace
