// `optimise` on a FEMM model (issue 31): the coarse annular valve exported to a .fem with its gap
// sidecar, the [optimise] table in the sidecar, the coil current as the design variable. The
// optimum is known in closed form, and the written CASE_optimal.fem solves to what the optimiser
// reported.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli_run.hpp"
#include "tests/optimise/optimise_fixture.hpp"

namespace {

using namespace optimise_fixture;
using rheomag::cli_test::run_rheomag;

// dp_on rises with the current and the coil power is I^2 R, so with the power capped the
// optimum current is sqrt(P_max / R): the cap binds.
const std::string kCurrentUnderAPowerCap = R"(
[optimise]
objective = "dp_on"
flow = 6.91e-6
max_iterations = 30
[[optimise.variable]]
key = "circuit.current"
lower = 0.2
upper = 2.0
[[optimise.constraint]]
quantity = "power"
max = 2.0
)";

TEST(OptimiseFem, CurrentUnderAPowerCapReachesTheClosedFormOptimumAndItsFemSolves) {
  // Reference: I* = sqrt(P_max / R) with R the coil resistance the optimiser reports (the wire's
  // resistance does not depend on the current). Tolerance 0.5 % on I* (Ipopt's tolerance 1e-4
  // on the scaled problem, the cap active). The written .fem is meshed anew from its labels, so
  // `valve` on it is held to 1 % of the optimiser's dp_on (FemmChain.* hold the .fem chain to
  // the case within 1 %).
  const TempDir dir("fem");
  std::ofstream(dir.path / "coarse.toml") << kBase;
  const auto exported = run_rheomag("export coarse.toml --fem v.fem", dir.path);
  ASSERT_EQ(exported.code, 0) << exported.err;
  std::ofstream(dir.path / "v.toml", std::ios::app) << kCurrentUnderAPowerCap;

  const auto run = run_rheomag("optimise v.fem --out out --json --quiet", dir.path);
  ASSERT_EQ(run.code, 0) << run.err << run.out;
  const nlohmann::json result = nlohmann::json::parse(run.out);
  const nlohmann::json& optimal = result["optimal"];
  const double current = optimal["variables"]["circuit.current"];
  const double resistance = optimal["quantities"]["resistance"];
  const double power = optimal["quantities"]["power"];
  const double dp_on = optimal["quantities"]["dp_on"];
  const double expected = std::sqrt(2.0 / resistance);
  std::printf(
      "optimum on the .fem: I %.6g A, sqrt(P_max / R) %.6g A (R %.6g ohm, %+.3f %%), "
      "power %.6g W, dp_on %.6g Pa\n",
      current, expected, resistance, 100.0 * (current / expected - 1.0), power, dp_on);
  EXPECT_NEAR(current, expected, 0.005 * expected);
  EXPECT_LE(power, 2.0 * (1.0 + 1e-3));
  EXPECT_GT(current, 0.2 * 1.01) << "the optimiser did not move from the lower bound";

  ASSERT_TRUE(fs::exists(dir.path / "out" / "v_optimal.fem"));
  ASSERT_TRUE(fs::exists(dir.path / "out" / "v_optimal.toml")) << "the sidecar keeps the gaps";
  const auto solved = run_rheomag("valve out/v_optimal.fem --flow 6.91e-6 --json", dir.path);
  ASSERT_EQ(solved.code, 0) << solved.err;
  const nlohmann::json valve = nlohmann::json::parse(solved.out);
  const double dp_written = valve["points"][0]["dp_total"];
  std::printf("v_optimal.fem: valve dp %.6g Pa at its own current (%+.3f %% of dp_on)\n",
              dp_written, 100.0 * (dp_written / dp_on - 1.0));
  EXPECT_NEAR(dp_written, dp_on, 0.01 * dp_on);
}

}  // namespace
