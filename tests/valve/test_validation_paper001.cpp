// Validation against paper 001's measured peak pressure drops (meandering valve, MRF-132DG,
// bypass-cylinder rig; /work/shared/seeds/001_*.txt, Fig. 7 and text): at 35.53, 53.30 and
// 71.06 ml/s the peak dp rises from 0.65, 0.95, 1.35 MPa at 0 A to 6.42, 6.53, 6.86 MPa at 1 A,
// predicted with the bundled meandering_valve case (FE field, MRF-132DG datasheet data,
// field-integrated exact Bingham gaps, plus the case's [valve] passages and minor losses: the
// unmagnetised core/spacer annulus, the ports, entrance/exit/turn losses).
// Result (measured when written, see docs/validation.md): on-state (1 A) -7 % to -10 %
// unscaled; with ONE yield-stress scale for the valve (fitted to the on-state points only,
// since the scale cannot touch the viscous off-state) within 2 %. Off-state (0 A): the gaps
// alone give 26-28 % of the measurement; with the passages and losses 46-50 %. The rest is not
// modelled (see docs/validation.md). The tolerances below pin these facts; the gaps-only
// numbers are printed for the before/after table.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "case/case_file.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "valve/solved_valve.hpp"
#include "valve/valve_chain.hpp"

using namespace rheomag;

TEST(ValidationPaper001, PeakPressureDropWithOneYieldStressScale) {
  const auto c = cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/meandering_valve.toml");
  const valve::ValveOptions options = valve::read_valve_options(c);
  ASSERT_FALSE(options.passages.empty());
  const valve::ValveOptions gaps_only;
  const fluid::Fluid fluid = valve::case_fluid(c);
  const std::vector<double> flows{35.53e-6, 53.30e-6, 71.06e-6};
  const std::vector<double> measured_off{0.65e6, 0.95e6, 1.35e6};
  const std::vector<double> measured_on{6.42e6, 6.53e6, 6.86e6};
  // One mesh, the field solved at 0 A and 1 A; both flow paths evaluated in the same fields.
  ASSERT_EQ(c.problem.circuits.at(0).current, 1.0);
  auto solved = magnetostatics::solve_problem(c.problem);  // at the case's 1 A
  const auto solution_off = solved.solver->solve({0.0});
  const auto results_off = magnetostatics::compute_results(*solved.solver, solution_off);
  std::vector<valve::ValvePoint> on, off, on_gaps, off_gaps;
  for (double current : {0.0, 1.0}) {
    const auto& solution = current == 0.0 ? solution_off : solved.solution;
    const auto& results = current == 0.0 ? results_off : solved.results;
    const valve::SolvedValve full(*solved.solver, solution, results, fluid, options);
    const valve::SolvedValve gaps(*solved.solver, solution, results, fluid, gaps_only);
    for (double q : flows) {
      (current == 0.0 ? off : on).push_back(full.point(q));
      (current == 0.0 ? off_gaps : on_gaps).push_back(gaps.point(q));
    }
  }
  // One scale s of the yield part minimising sum ((s p_yield + p_visc - m)/m)^2 over the
  // on-state points.
  auto fit_scale = [&](const std::vector<valve::ValvePoint>& points) {
    double num = 0.0, den = 0.0;
    for (std::size_t k = 0; k < flows.size(); ++k) {
      const double y = points[k].dp_yield / measured_on[k];
      const double v = points[k].dp_viscous / measured_on[k];
      num += y * (1.0 - v), den += y * y;
    }
    return num / den;
  };
  const double scale = fit_scale(on), scale_gaps = fit_scale(on_gaps);
  std::printf("paper 001: yield-stress scale %.3f (gaps only: %.3f)\n", scale, scale_gaps);
  for (std::size_t k = 0; k < flows.size(); ++k) {
    const double scaled = scale * on[k].dp_yield + on[k].dp_viscous;
    const double raw_error = on[k].dp_total / measured_on[k] - 1.0;
    const double scaled_error = scaled / measured_on[k] - 1.0;
    const double off_ratio = off[k].dp_total / measured_off[k];
    const double gaps_scaled = scale_gaps * on_gaps[k].dp_yield + on_gaps[k].dp_viscous;
    std::printf(
        "  Q=%.2f ml/s: 1 A measured %.2f MPa, predicted %.3f MPa (%+.1f %%), scaled %+.1f %%"
        " [gaps only %.3f (%+.1f %%), scaled %+.1f %%];\n"
        "    0 A measured %.2f MPa, predicted %.3f MPa (%+.0f %%) [gaps only %.3f (%+.0f %%)]\n",
        flows[k] * 1e6, measured_on[k] * 1e-6, on[k].dp_total * 1e-6, 100 * raw_error,
        100 * scaled_error, on_gaps[k].dp_total * 1e-6,
        100 * (on_gaps[k].dp_total / measured_on[k] - 1.0),
        100 * (gaps_scaled / measured_on[k] - 1.0), measured_off[k] * 1e-6, off[k].dp_total * 1e-6,
        100 * (off_ratio - 1.0), off_gaps[k].dp_total * 1e-6,
        100 * (off_gaps[k].dp_total / measured_off[k] - 1.0));
    EXPECT_LT(std::abs(raw_error), 0.15) << "unscaled on-state, Q=" << flows[k];
    EXPECT_LT(std::abs(scaled_error), 0.05) << "scaled on-state, Q=" << flows[k];
    // Known gap: off-state predicted at about half the measurement (see header).
    EXPECT_GT(off_ratio, 0.40) << "Q=" << flows[k];
    EXPECT_LT(off_ratio, 0.60) << "Q=" << flows[k];
    // The passages and losses are field-independent: they add the same to both states.
    EXPECT_NEAR(on[k].dp_viscous - on_gaps[k].dp_viscous, off[k].dp_total - off_gaps[k].dp_total,
                1e-9 * off[k].dp_total);
  }
  EXPECT_GT(scale, 0.9);
  EXPECT_LT(scale, 1.3);
}
