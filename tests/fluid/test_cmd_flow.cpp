// The `rheomag flow` command: JSON keys and values against the library, and exit code 2 on bad
// input. Runs the built CLI (RHEOMAG_BINARY).

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "fluid/annulus_bingham.hpp"
#include "fluid/mixed_mode.hpp"
#include "fluid/radial_bingham.hpp"
#include "fluid/shear_mode.hpp"
#include "fluid/slit_bingham.hpp"
#include "tests/cli_run.hpp"

using namespace rheomag::fluid;

namespace {

using rheomag::cli_test::CliRun;

CliRun run(const std::string& args) {
  return rheomag::cli_test::run_rheomag(args);
}

double json_number(const std::string& json, const std::string& key) {
  const std::regex pattern("\"" + key + "\": *([-+0-9.eE]+)");
  std::smatch match;
  if (!std::regex_search(json, match, pattern)) {
    ADD_FAILURE() << "key " << key << " missing in " << json;
    return NAN;
  }
  return std::stod(match[1]);
}

void expect_matches(const std::string& json, const GapPressureDrop& ref) {
  // Reference: the library call with the same inputs; the CLI prints 12 significant digits.
  EXPECT_NEAR(json_number(json, "dp") / ref.dp, 1.0, 1e-10) << json;
  EXPECT_NEAR(json_number(json, "dp_viscous") / ref.dp_viscous, 1.0, 1e-10);
  EXPECT_NEAR(json_number(json, "dp_yield") / ref.dp_yield, 1.0, 1e-9);
  EXPECT_NEAR(json_number(json, "plug_fraction"), ref.plug_fraction, 1e-11);
  EXPECT_NEAR(json_number(json, "bingham_number") / ref.bingham_number, 1.0, 1e-10);
  // dp_yield is defined as dp - dp_viscous.
  EXPECT_NEAR(json_number(json, "dp_yield"),
              json_number(json, "dp") - json_number(json, "dp_viscous"),
              1e-9 * json_number(json, "dp"));
}

}  // namespace

TEST(CmdFlow, AnnularExactAndApproxJson) {
  const std::string common =
      "flow --kind annular --gap 1e-3 --length 0.01 --radius 0.0195 --tau-y 20000 "
      "--viscosity 0.106 --flow 1e-6 --json";
  const AnnulusGeometry g{1e-3, 0.0195, 0.01};
  const CliRun exact = run(common);
  ASSERT_EQ(exact.code, 0) << exact.out;
  expect_matches(exact.out, annulus_bingham(g, 2e4, 0.106, 1e-6));
  const CliRun approx = run(common + " --model approx");
  ASSERT_EQ(approx.code, 0);
  expect_matches(approx.out, annulus_paper000(g, 2e4, 0.106, 1e-6));
  // Sanity of magnitude: dp ~ 2 tau_y L / h = 4 bar for Bi >> 1 (slit limit c -> 2).
  EXPECT_NEAR(json_number(exact.out, "dp") / 4e5, 1.0, 0.05);
}

TEST(CmdFlow, RadialJson) {
  const CliRun r =
      run("flow --kind radial --gap 0.5e-3 --r-in 0.005 --r-out 0.02 --tau-y 3e4 --viscosity 0.11 "
          "--flow 2e-5 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  expect_matches(r.out, radial_bingham(RadialGeometry{0.5e-3, 0.005, 0.02}, 3e4, 0.11, 2e-5));
}

TEST(CmdFlow, BadInputExitsTwo) {
  const std::string tail = " --tau-y 1e4 --viscosity 0.1 --flow 1e-6";
  for (const std::string& args : std::vector<std::string>{
           "flow --kind annular --gap 0 --length 0.01 --radius 0.02" + tail,
           "flow --kind annular --gap -1e-3 --length 0.01 --radius 0.02" + tail,
           "flow --kind annular --gap 1e-3 --length 0.01 --radius 0.02 --tau-y 1e4 "
           "--viscosity 0 --flow 1e-6",
           "flow --kind annular --gap 1e-3 --length 0.01 --radius 0.02 --tau-y 1e4 "
           "--viscosity 0.1 --flow -1e-6",
           "flow --kind annular --gap 1e-3 --length 0.01" + tail,            // no --radius
           "flow --kind radial --gap 1e-3 --r-in 0.02 --r-out 0.01" + tail,  // r_out <= r_in
           "flow --kind radial --gap 1e-3 --r-in 0.01" + tail,               // no --r-out
           "flow --kind radial --gap 1e-3 --r-in 0.01 --r-out 0.02 --length 0.1" + tail,
           "flow --kind annular --gap 1e-3 --length 0.01 --radius 0.02 --tau-y -5 "
           "--viscosity 0.1 --flow 1e-6",
           "flow --kind conical --gap 1e-3" + tail,
           "flow --kind annular --gap 1e-3 --length 0.01 --radius 0.02 --model magic" + tail,
       }) {
    const CliRun r = run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_TRUE(r.out.empty()) << args << " printed " << r.out;
  }
}

// Reference: the library call with the same inputs (the CLI prints 12 significant digits).
TEST(CmdShear, DrumAndDiscJson) {
  const CliRun drum =
      run("shear --kind drum --r-in 0.02 --r-out 0.021 --length 0.03 --tau-y 2e4 --viscosity 0.1 "
          "--speed 10 --json");
  ASSERT_EQ(drum.code, 0) << drum.out;
  const ShearTorque t =
      drum_torque(DrumGeometry{0.02, 0.021, 0.03}, GapRheology{2e4, 0.1, 1.0}, 10.0);
  EXPECT_NEAR(json_number(drum.out, "torque") / t.torque, 1.0, 1e-10);
  EXPECT_NEAR(json_number(drum.out, "torque_yield") / t.torque_yield, 1.0, 1e-9);
  EXPECT_NEAR(json_number(drum.out, "torque_viscous") / t.torque_viscous, 1.0, 1e-10);
  EXPECT_NEAR(json_number(drum.out, "yielded_fraction"), t.yielded_fraction, 1e-11);
  const CliRun disc =
      run("shear --kind disc --r-in 0.01 --r-out 0.05 --gap 1e-3 --faces 2 --tau-y 3e4 "
          "--viscosity 0.1 --speed -50 --json");
  ASSERT_EQ(disc.code, 0) << disc.out;
  const ShearTorque d =
      disc_torque(DiscGeometry{0.01, 0.05, 1e-3, 2}, GapRheology{3e4, 0.1, 1.0}, -50.0);
  EXPECT_NEAR(json_number(disc.out, "torque") / d.torque, 1.0, 1e-10);
  EXPECT_LT(json_number(disc.out, "torque"), 0.0);
  EXPECT_EQ(json_number(disc.out, "yielded_fraction"), 1.0);
}

// Reference: fluid::slit_mixed_mode / annulus_mixed_mode with the same inputs; the regime name.
TEST(CmdShear, FlowWithWallVelocityAndSlit) {
  const CliRun slit =
      run("flow --kind slit --gap 1e-3 --width 0.05 --length 0.02 --tau-y 2e4 --viscosity 0.1 "
          "--flow 1e-7 --wall-velocity 0.1 --json");
  ASSERT_EQ(slit.code, 0) << slit.out;
  const MixedModeDrop s =
      slit_mixed_mode(SlitGeometry{1e-3, 0.05, 0.02}, GapRheology{2e4, 0.1, 1.0}, 0.1, 1e-7);
  EXPECT_NEAR(json_number(slit.out, "dp"), s.drop.dp, 1e-10 * std::abs(s.drop.dp));
  EXPECT_NEAR(json_number(slit.out, "wall_velocity"), 0.1, 1e-15);
  EXPECT_NE(slit.out.find("\"regime\": \"" + std::string(kMixedRegimeNames.name(s.regime)) + "\""),
            std::string::npos)
      << slit.out;
  // A negative flow with a moving wall is a direction; dp may come out negative.
  const CliRun back = run(
      "flow --kind annular --gap 1e-3 --length 0.02 --radius 0.0195 --tau-y 2e4 --viscosity 0.1 "
      "--flow -1e-6 --wall-velocity -0.1 --json");
  ASSERT_EQ(back.code, 0) << back.out;
  EXPECT_LT(json_number(back.out, "dp"), 0.0);
}

TEST(CmdShear, BadInputExitsTwo) {
  for (const std::string& args : std::vector<std::string>{
           "shear --kind drum --r-in 0.02 --r-out 0.02 --length 0.03 --tau-y 1 --viscosity 0.1 "
           "--speed 1",
           "shear --kind drum --r-in 0.03 --r-out 0.02 --length 0.03 --tau-y 1 --viscosity 0.1 "
           "--speed 1",
           "shear --kind drum --r-in 0.02 --r-out 0.03 --length 0.03 --tau-y 1 --viscosity -0.1 "
           "--speed 1",
           "shear --kind drum --r-in 0.02 --r-out 0.03 --tau-y 1 --viscosity 0.1 --speed 1",
           "shear --kind disc --r-in 0.01 --r-out 0.05 --gap 0 --tau-y 1 --viscosity 0.1 --speed 1",
           "shear --kind disc --r-in 0.01 --r-out 0.05 --gap -1e-3 --tau-y 1 --viscosity 0.1 "
           "--speed 1",
           "shear --kind disc --r-in 0.01 --r-out 0.05 --gap 1e-3 --length 1 --tau-y 1 --viscosity "
           "0.1 --speed 1",
           "shear --kind cone --r-in 0.01 --r-out 0.05 --tau-y 1 --viscosity 0.1 --speed 1",
           "flow --kind slit --gap 1e-3 --length 0.02 --tau-y 1 --viscosity 0.1 --flow 1e-6",
           "flow --kind slit --gap 1e-3 --width 0.05 --length 0.02 --radius 0.01 --tau-y 1 "
           "--viscosity 0.1 --flow 1e-6",
           "flow --kind radial --gap 1e-3 --r-in 0.01 --r-out 0.02 --tau-y 1 --viscosity 0.1 "
           "--flow 1e-6 --wall-velocity 0.1",
           "flow --kind annular --gap 1e-3 --length 0.02 --radius 0.02 --tau-y 1 --viscosity 0.1 "
           "--flow 1e-6 --wall-velocity 0.1 --model approx",
           "flow --kind slit --gap 1e-3 --width 0.05 --length 0.02 --tau-y 1 --viscosity -0.1 "
           "--flow 1e-6 --wall-velocity 0.1",
       }) {
    const CliRun r = run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_TRUE(r.out.empty()) << args << " printed " << r.out;
  }
}
