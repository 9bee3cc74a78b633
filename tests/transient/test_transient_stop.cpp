// A run that ends once every fluid gap has made a fraction of its change
// (TransientOptions::stop_at_gap_fraction, what response_time asks for): its rise times are the
// whole run's bit for bit, it ends at the first step past the slowest gap's crossing, and a
// fraction outside [0, 1] is refused.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "transient/from_case.hpp"

namespace {

using namespace rheomag;
using transient::Drive;

// The radial valve (two gaps) driven by 12 V through 3 Ohm, 25 equal steps over 0.1 s.
transient::TransientOptions valve_step() {
  transient::TransientOptions o = transient::step_options(Drive::voltage, 12.0, 0.1);
  o.resistance = 3.0;
  o.steps = 25;
  o.check_steps = false;
  return o;
}

TEST(TransientStop, RunEndedAtTheGapsT90HasTheWholeRunsRiseTimes) {
  // Reference: the same run over the whole duration. Rise times are first crossings, so a run
  // stopped after the slowest gap's t90 has the same series up to there, and the same t63 and
  // t90 of every gap, exactly (tolerance 0).
  const cases::Case c =
      cases::load_case(std::filesystem::path(RHEOMAG_SOURCE_DIR) / "cases" / "radial_valve.toml");
  const transient::CaseTransient set_up = transient::transient_from_case(c);
  transient::TransientOptions o = valve_step();
  const transient::TransientResult whole = set_up.solver->run(o);
  o.stop_at_gap_fraction = 0.9;
  const transient::TransientResult stopped = set_up.solver->run(o);

  ASSERT_FALSE(whole.gaps.empty());
  ASSERT_EQ(stopped.gaps.size(), whole.gaps.size());
  double slowest = 0.0;
  for (std::size_t g = 0; g < whole.gaps.size(); ++g) {
    ASSERT_TRUE(whole.gaps[g].t90 && stopped.gaps[g].t90) << whole.gaps[g].name;
    EXPECT_EQ(*stopped.gaps[g].t90, *whole.gaps[g].t90) << whole.gaps[g].name;
    EXPECT_EQ(stopped.gaps[g].t63, whole.gaps[g].t63) << whole.gaps[g].name;
    slowest = std::max(slowest, *whole.gaps[g].t90);
  }
  EXPECT_FALSE(whole.stopped_early);
  EXPECT_TRUE(stopped.stopped_early);
  EXPECT_LT(stopped.steps, whole.steps);
  // It ends at the first step past the slowest crossing.
  ASSERT_GE(stopped.time.size(), 2u);
  EXPECT_LT(stopped.time[stopped.time.size() - 2], slowest);
  EXPECT_GE(stopped.time.back(), slowest);
  for (std::size_t k = 0; k < stopped.time.size(); ++k)
    ASSERT_EQ(stopped.flux_linkage[k], whole.flux_linkage[k]) << "sample " << k;
  std::printf("slowest gap t90 %.6g s: %d of %d steps\n", slowest, stopped.steps, whole.steps);
}

TEST(TransientStop, FractionOutsideZeroToOneIsRefused) {
  const cases::Case c =
      cases::load_case(std::filesystem::path(RHEOMAG_SOURCE_DIR) / "cases" / "radial_valve.toml");
  const transient::CaseTransient set_up = transient::transient_from_case(c);
  transient::TransientOptions o = valve_step();
  for (const double bad : {-0.1, 1.5}) {
    o.stop_at_gap_fraction = bad;
    EXPECT_THROW(set_up.solver->run(o), InputError) << bad;
  }
}

}  // namespace
