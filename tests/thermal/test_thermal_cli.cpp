// `rheomag thermal` as a user meets it: JSON whose heat balance closes, the .vtu it writes, and
// bad input (issue 32: a negative conductivity, a negative convection coefficient, a duty
// outside [0, 1]) exiting 2 with the key or option named.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using rheomag::cli_test::run_rheomag;

const std::string kValve = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";

/// A copy of the reference valve with `extra` TOML appended, in a fresh folder.
fs::path valve_with(const std::string& name, const std::string& extra) {
  const fs::path dir = fs::temp_directory_path() / ("rheomag_thermal_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ifstream in(kValve);
  std::stringstream text;
  text << in.rdbuf() << "\n" << extra;
  std::ofstream(dir / "valve.toml") << text.str();
  return dir / "valve.toml";
}

TEST(ThermalCli, JsonBalancesAndVtkHoldsTheTemperature) {
  const fs::path dir = fs::temp_directory_path() / "rheomag_thermal_vtk";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto run =
      run_rheomag("thermal '" + kValve + "' --flow 1L/min --current 0.8 --json --vtk '" +
                  (dir / "t.vtu").string() + "'");
  ASSERT_EQ(run.code, 0) << run.err;
  const nlohmann::json j = nlohmann::json::parse(run.out);
  EXPECT_LT(std::abs(j["balance_error"].get<double>()), 1e-8);
  EXPECT_TRUE(j["coupled"].get<bool>());
  EXPECT_GT(j["temperatures"]["coil_mean"].get<double>(), j["ambient"].get<double>());
  EXPECT_DOUBLE_EQ(j["operating_point"]["value"].get<double>(), 1e-3 / 60.0);
  std::ifstream vtu(dir / "t.vtu");
  std::stringstream text;
  text << vtu.rdbuf();
  EXPECT_NE(text.str().find("Name=\"temperature\""), std::string::npos);
  EXPECT_NE(text.str().find("Name=\"heat_source\""), std::string::npos);
}

TEST(ThermalCli, BadInputExitsTwoNamingTheKey) {
  const auto duty = run_rheomag("thermal '" + kValve + "' --duty 1.5");
  EXPECT_EQ(duty.code, 2);
  EXPECT_NE(duty.err.find("--duty"), std::string::npos) << duty.err;
  const auto convection =
      run_rheomag("thermal '" + valve_with("h", "[thermal]\nconvection = -3.0\n").string() + "'");
  EXPECT_EQ(convection.code, 2);
  EXPECT_NE(convection.err.find("thermal.convection"), std::string::npos) << convection.err;
  const auto conductivity =
      run_rheomag("thermal '" +
                  valve_with("k",
                             "[[thermal.material]]\nname = \"AISI 1010\"\nconductivity = -50.0\n"
                             "density = 7870.0\nspecific_heat = 448.0\n")
                      .string() +
                  "'");
  EXPECT_EQ(conductivity.code, 2);
  EXPECT_NE(conductivity.err.find("conductivity"), std::string::npos) << conductivity.err;
  const auto both = run_rheomag("thermal '" + kValve + "' --flow 1e-6 --speed 3");
  EXPECT_EQ(both.code, 2);
  const auto region = run_rheomag(
      "thermal '" +
      valve_with("r", "[[thermal.surface]]\nregions = [\"no_such\"]\nconvection = 5.0\n").string() +
      "'");
  EXPECT_EQ(region.code, 2);
  EXPECT_NE(region.err.find("no_such"), std::string::npos) << region.err;
}

}  // namespace
