// valve::SolvedValve: the valve chain evaluated from a field that is already solved (as the
// sweep and the optimiser use it), checked against ValveChain, which solves the field itself.

#include <gtest/gtest.h>

#include <cmath>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "fluid/newtonian.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "valve/solved_valve.hpp"
#include "valve/valve_chain.hpp"

using namespace rheomag;

namespace {

const std::string kCase = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";

}  // namespace

// Reference: ValveChain::evaluate at the case's current (1 A) on a fresh solver of the same
// mesh is the same FE solve, so every number must agree to rounding (1e-12 relative).
// Off state: with B = 0 the gaps are Newtonian annuli (tau_y(0) = 0 for MRC-C1L), the exact
// annulus Poiseuille drop x 2 poles within 1e-9.
TEST(SolvedValve, EqualsValveChainAndGivesTheZeroFieldPath) {
  const auto c = cases::load_case(kCase);
  valve::ValveOptions options;
  options.wire = "AWG 24";
  const auto solved = magnetostatics::solve_problem(c.problem);
  const fluid::Fluid fluid = valve::case_fluid(c);
  const valve::SolvedValve valve(*solved.solver, solved.solution, solved.results, fluid, options);
  valve::ValveChain chain(c, options);
  const double current = c.problem.circuits.at(0).current;
  for (double flow : {1e-6, 5e-6}) {
    const auto direct = chain.evaluate({current}, {flow}).at(0);
    const auto p = valve.point(flow);
    EXPECT_EQ(p.current, current);
    EXPECT_NEAR(p.dp_total / direct.dp_total, 1.0, 1e-12);
    EXPECT_NEAR(p.dp_total_average_b / direct.dp_total_average_b, 1.0, 1e-12);
    EXPECT_NEAR(p.inductance / direct.inductance, 1.0, 1e-12);
    ASSERT_EQ(p.segments.size(), direct.segments.size());
    EXPECT_GT(p.dp_yield, 0.0);
    const auto off = valve.zero_field_point(flow);
    const double poiseuille =
        2.0 * fluid::annulus_poiseuille_dp(fluid::AnnulusGeometry{1e-3, 19.5e-3, 5e-3},
                                           fluid.viscosity, flow);
    EXPECT_NEAR(off.dp_total / poiseuille, 1.0, 1e-9);
    EXPECT_EQ(off.dp_yield, 0.0);
  }
  EXPECT_NEAR(valve.min_clearance(), 1e-3, 1e-9);
  EXPECT_GT(valve.b_average(), 0.1);
  const auto spec = valve::coil_spec(*solved.solver, options);
  EXPECT_EQ(spec.turns, chain.turns());
  EXPECT_EQ(spec.wire_diameter, cases::wire_diameter("AWG 24"));
  EXPECT_THROW(valve.point(0.0), InputError);
}
