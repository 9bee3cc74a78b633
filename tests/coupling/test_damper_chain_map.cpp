// The lumped damper rig driven by the map the FE chain predicts for the bundled piston case
// (cases/rigs/damper_chain.toml -> cases/damper_piston.toml): at constant velocity and current
// its force is the damper chain's force.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "case/case_file.hpp"
#include "coupling/simulation_spec.hpp"
#include "coupling/valve_chain_tabulation.hpp"
#include "lumped/signals.hpp"
#include "valve/damper.hpp"

using namespace rheomag;
using namespace rheomag::lumped;
using namespace rheomag::coupling;

namespace {
std::string source(const std::string& rel) {
  return std::string(RHEOMAG_SOURCE_DIR) + "/" + rel;
}
}  // namespace

// Reference: valve::DamperChain on the same case. The table holds (F - F_gas)/A_eff at its own
// grid flows (1e-8 relative there); a rig with the case's area and gas force, driven at a
// constant 0.1 m/s and a constant current, settles on F = A p + F_gas,
// which must be the chain's force within 1 % (linear interpolation between the log-spaced grid
// flows, 12 points over three decades).
TEST(DamperChainMap, RigForceIsTheChainForce) {
  const std::string case_file = source("cases/damper_piston.toml");
  const auto table = tabulate_valve_chain(case_file, 1.0, 2e-4, 3, 12);
  const auto c = cases::load_case(case_file);
  valve::DamperChain chain(c, valve::read_damper_options(c));
  const auto at_grid = chain.evaluate_flows({0.5}, {table->flow[6]});
  const double area = at_grid[0].flow / at_grid[0].velocity;
  const double dp = chain_pressure_drop(*table, table->flow[6], 0.5, 1.0, 1.0, 1e-12);
  EXPECT_NEAR(dp * area, at_grid[0].force - at_grid[0].force_gas, 1e-8 * at_grid[0].force);

  const SimulationSpec spec = read_simulation_spec(source("cases/rigs/damper_chain.toml"));
  for (double current : {0.0, 1.0}) {
    Recording drive;
    drive.t = uniform_times(0.5, 200.0);
    add_signal(drive, "velocity=constant:value=0.1");
    add_signal(drive, "current=constant:value=" + std::to_string(current));
    const Recording rec = simulate_spec(spec, drive);
    const double force = rec.column("force").back();
    const double ref = chain.evaluate({current}, {0.1})[0].force;
    EXPECT_NEAR(force, ref, 0.01 * ref) << current;
  }
}
