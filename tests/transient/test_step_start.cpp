// Where a step's Newton starts (TransientOptions::choose_start): from the extrapolation through
// the last states or from the last state, whichever has the smaller residual.
// References and tolerances:
// - the answer is the same run's with the start always extrapolated (the method before): every
//   sample of the flux linkage, the current and the gaps' mean |B| within 1e-7 of its range
//   (Newton stops at a relative residual of 1e-8; measured 2e-11 to 4e-10);
// - on long midpoint steps of a saturating valve under a voltage step, the extrapolation through
//   ringing states starts further off: the chosen start must save at least a fifth of the Newton
//   iterations and of the factorisations (measured on this run: 153 -> 110 iterations,
//   96 -> 55 factorisations);
// - on short steps after a current step, where the extrapolation is the better start, the chosen
//   start takes no more Newton iterations than always extrapolating.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "case/case_file.hpp"
#include "transient/from_case.hpp"

namespace {

using namespace rheomag;

cases::Case radial_valve() {
  return cases::load_case(std::filesystem::path(RHEOMAG_SOURCE_DIR) / "cases" /
                          "radial_valve.toml");
}

/// Largest difference between two series relative to the range of the first.
double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  const auto [lo, hi] = std::minmax_element(a.begin(), a.end());
  double worst = 0.0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
    worst = std::max(worst, std::abs(a[k] - b[k]));
  return worst / std::max(*hi - *lo, 1e-300);
}

void expect_same_response(const transient::TransientResult& chosen,
                          const transient::TransientResult& extrapolated) {
  ASSERT_EQ(chosen.steps, extrapolated.steps);
  EXPECT_LT(relative_difference(extrapolated.flux_linkage, chosen.flux_linkage), 1e-7);
  EXPECT_LT(relative_difference(extrapolated.current, chosen.current), 1e-7);
  ASSERT_EQ(chosen.gaps.size(), extrapolated.gaps.size());
  for (std::size_t g = 0; g < chosen.gaps.size(); ++g)
    EXPECT_LT(relative_difference(extrapolated.gaps[g].b_avg, chosen.gaps[g].b_avg), 1e-7)
        << chosen.gaps[g].name;
}

TEST(StepStart, LongStepsAfterAVoltageStepStartFromTheSmallerResidual) {
  // The bundled radial valve driven by 12 V through 3 Ohm (its steel saturating) over 60 ms in 15
  // equal midpoint steps of 4 ms, a tenth of its t90: the conductors' stiff modes ring.
  const transient::CaseTransient set_up = transient::transient_from_case(radial_valve());
  transient::TransientOptions o = transient::step_options(transient::Drive::voltage, 12.0, 0.06);
  o.resistance = 3.0;
  o.steps = 15;
  o.check_steps = false;
  const transient::TransientResult chosen = set_up.solver->run(o);
  o.choose_start = false;
  const transient::TransientResult extrapolated = set_up.solver->run(o);

  expect_same_response(chosen, extrapolated);
  std::printf("Newton iterations %d -> %d, factorisations %d -> %d\n",
              extrapolated.newton_iterations, chosen.newton_iterations, extrapolated.factorizations,
              chosen.factorizations);
  EXPECT_LE(chosen.newton_iterations, 0.8 * extrapolated.newton_iterations);
  EXPECT_LE(chosen.factorizations, 0.8 * extrapolated.factorizations);
}

TEST(StepStart, ShortStepsAfterACurrentStepKeepTheExtrapolation) {
  // Adaptive steps after a 1 A current step: the field enters the steel smoothly, and the
  // extrapolation is the nearer start at nearly every step.
  const transient::CaseTransient set_up = transient::transient_from_case(radial_valve());
  transient::TransientOptions o = transient::step_options(transient::Drive::current, 1.0, 0.02);
  const transient::TransientResult chosen = set_up.solver->run(o);
  o.choose_start = false;
  const transient::TransientResult extrapolated = set_up.solver->run(o);

  expect_same_response(chosen, extrapolated);
  std::printf("Newton iterations %d -> %d\n", extrapolated.newton_iterations,
              chosen.newton_iterations);
  EXPECT_LE(chosen.newton_iterations, extrapolated.newton_iterations);
}

}  // namespace
