// The valve-chain grey-box model: its static map equals the fluid chain at the table's points,
// the inverse map undoes the map, and a fit recovers the parameters of a recording simulated by
// the bundled spec cases/rigs/constant_velocity_pump_chain.toml (chain map of the FE case
// cases/annular_valve.toml); a sidecar without a valve case is rejected.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "coupling/simulation_spec.hpp"
#include "coupling/valve_chain_tabulation.hpp"
#include "identify/valve_chain_fit.hpp"
#include "lumped/signals.hpp"
#include "valve/valve_chain.hpp"

using namespace rheomag::lumped;
using namespace rheomag::identify;
using namespace rheomag::coupling;

namespace {

std::string source(const std::string& rel) {
  return std::string(RHEOMAG_SOURCE_DIR) + "/" + rel;
}

}  // namespace

// At the table's own grid points the map is the chain's total dp (the yield and viscous parts
// are stored separately and re-added, R as the mean dp_viscous / Q: 1e-8 relative). Between points
// the flow is interpolated linearly; the inverse map returns the flow it was given (1e-9 relative +
// the sign regularisation width, which shifts |Q| by eps) beyond the plug, and zero flow inside it.
TEST(ValveChain, MapMatchesTheChainAndInverts) {
  const std::string case_file = source("cases/annular_valve.toml");
  const auto table = tabulate_valve_chain(case_file, 1.0, 2e-5, 3, 6);
  const auto c = rheomag::cases::load_case(case_file);
  rheomag::valve::ValveChain chain(c, rheomag::valve::read_valve_options(c));
  const auto points = chain.evaluate({0.5}, {table->flow[3]});
  const double eps = 1e-12;  // sign regularisation far below the grid flows
  const double dp = chain_pressure_drop(*table, table->flow[3], 0.5, 1.0, 1.0, eps);
  EXPECT_NEAR(dp, points[0].dp_total, 1e-8 * points[0].dp_total);
  for (double q : {3e-7, 4e-6, 1.7e-5, -9e-6}) {
    const double p = chain_pressure_drop(*table, q, 0.8, 0.6, 2.0, eps);
    EXPECT_NEAR(chain_flow(*table, p, 0.8, 0.6, 2.0, eps), q, 1e-9 * std::abs(q) + 5 * eps) << q;
  }
  const double plug = 0.6 * table->yield_at(0, 0.8);
  EXPECT_NEAR(chain_flow(*table, 0.9 * plug, 0.8, 0.6, 2.0, eps), 0.0, 1e-15);
}

// Recovery from the model's own recording: the bundled spec (yield scale 0.471, viscous scale 1,
// field lag 0.1 s, linear chamber compliance C = V / (2 beta) = 5e-5 / (2 x 4.5e6) =
// 5.56e-12 m^3/Pa across the valve) driven by a 20 mm, 1 Hz sine and current steps, with 2 kPa
// pressure noise (0.25 % of the peak), 6 s at 100 Hz, 2 starts. Tolerances: yield scale 2 %,
// lag and compliance 5 %, viscous scale 10 % (its drop is ~1 % of the yield drop here; standard
// error 2 %); measured -0.14 %, -0.45 %, -0.05 %, -0.2 %, FIT 99.6 % (> 97 % required).
TEST(ValveChain, FitRecoversItsOwnParameters) {
  const SimulationSpec spec =
      read_simulation_spec(source("cases/rigs/constant_velocity_pump_chain.toml"));
  Recording drive;
  drive.t = uniform_times(6.0, 100.0);
  add_signal(drive, "displacement=sine:amplitude=0.02,frequency=1");
  add_signal(drive, "current=steps:levels=0/1/0.5,period=2");
  SimulationSpec noisy = spec;
  noisy.rig->sensor_noise["pressure"] = 2e3;
  noisy.rig->noise_seed = 3;
  Recording rec = simulate_spec(noisy, drive);
  rec.meta.sidecar_path = "simulated.toml";
  ASSERT_FALSE(rec.meta.valve.case_file.empty());

  ValveChainFitOptions options;
  options.starts = 2;
  const ValveChainFit fit = fit_valve_chain(rec, options);
  auto value = [&](const std::string& name) {
    for (const auto& p : fit.params)
      if (p.name == name) return p.value;
    ADD_FAILURE() << name;
    return 0.0;
  };
  EXPECT_NEAR(value("yield_scale"), 0.471, 0.02 * 0.471);
  EXPECT_NEAR(value("field_time_constant"), 0.1, 0.05 * 0.1);
  EXPECT_NEAR(value("hydraulic_capacitance"), 5e-5 / (2 * 4.5e6), 0.05 * 5e-5 / (2 * 4.5e6));
  EXPECT_NEAR(value("viscous_scale"), 1.0, 0.10);
  EXPECT_GT(fit.train.fit_percent, 97.0);
  for (const auto& p : fit.params) EXPECT_TRUE(p.standard_error.has_value()) << p.name;
}

// A sidecar whose [valve] is a Bingham table (no FE case) cannot feed the fluid chain.
TEST(ValveChain, SidecarWithoutValveCaseIsRejected) {
  const SimulationSpec spec =
      read_simulation_spec(source("cases/rigs/constant_velocity_pump.toml"));
  Recording drive;
  drive.t = uniform_times(1.0, 100.0);
  add_signal(drive, "displacement=sine:amplitude=0.01,frequency=0.5");
  add_signal(drive, "current=constant:value=0.5");
  Recording rec = simulate_spec(spec, drive);
  rec.meta.sidecar_path = "bingham_rig.toml";
  try {
    fit_valve_chain(rec);
    FAIL() << "expected InputError";
  } catch (const rheomag::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bingham_rig.toml: [valve] has no 'case'"),
              std::string::npos)
        << e.what();
  }
}
