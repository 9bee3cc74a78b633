// A FEMM model through the chain (issue 31): `export` writes the model and its gap sidecar,
// `valve` runs on the model as on the case, and the bad inputs exit 2 naming what is wrong.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using rheomag::cli_test::run_rheomag;

const std::string kCase = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";

/// A fresh directory for one test's files.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rheomag_femm_chain_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(FemmChain, ExportedValveRunsTheChainLikeItsCase) {
  // Reference: the same valve from its TOML case. Tolerance 1 % on the pressure drop: the .fem
  // is meshed anew from its label sizes, and its flux linkage agrees with the case's within
  // 0.5 % (FemmExport.AnnularValveRoundTrip); the gap |B| carries that difference into dp.
  const fs::path dir = scratch("export");
  const auto exported = run_rheomag("export '" + kCase + "' --fem v.fem", dir);
  ASSERT_EQ(exported.code, 0) << exported.err;
  ASSERT_TRUE(fs::exists(dir / "v.toml")) << exported.out;
  const auto from_fem = run_rheomag("valve v.fem --flow 1e-6 --json", dir);
  ASSERT_EQ(from_fem.code, 0) << from_fem.err;
  const auto from_case = run_rheomag("valve '" + kCase + "' --flow 1e-6 --json");
  ASSERT_EQ(from_case.code, 0) << from_case.err;
  const auto fem = nlohmann::json::parse(from_fem.out), toml = nlohmann::json::parse(from_case.out);
  const double dp_fem = fem["points"][0]["dp_total"], dp_toml = toml["points"][0]["dp_total"];
  std::printf("valve at 1e-6 m^3/s: dp %.6g Pa from the .fem, %.6g Pa from the case (%+.3f %%)\n",
              dp_fem, dp_toml, 100.0 * (dp_fem / dp_toml - 1.0));
  EXPECT_NEAR(dp_fem, dp_toml, 0.01 * dp_toml);
  EXPECT_EQ(fem["fluid"], toml["fluid"]);
  ASSERT_EQ(fem["points"][0]["segments"].size(), toml["points"][0]["segments"].size());
  for (std::size_t k = 0; k < toml["points"][0]["segments"].size(); ++k)
    EXPECT_EQ(fem["points"][0]["segments"][k]["name"], toml["points"][0]["segments"][k]["name"]);
}

TEST(FemmChain, SidecarErrorsNameTheLabel) {
  const fs::path dir = scratch("sidecar");
  ASSERT_EQ(run_rheomag("export '" + kCase + "' --fem v.fem", dir).code, 0);
  {
    std::ofstream(dir / "v.toml") << "[fem]\n[[fem.gap]]\nlabel = [0.5, 0.5]\n";
    const auto run = run_rheomag("valve v.fem --flow 1e-6", dir);
    EXPECT_EQ(run.code, 2);
    EXPECT_NE(run.err.find("no block label at (0.5, 0.5) m"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("its labels are"), std::string::npos) << run.err;
  }
  {
    std::ofstream(dir / "v.toml") << "[fem]\n[[fem.gap]]\nblock = \"AISI 1010_1\"\n";
    const auto run = run_rheomag("solve v.fem", dir);
    EXPECT_EQ(run.code, 2);
    EXPECT_NE(run.err.find("block label 'AISI 1010_1'"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("is not an MR fluid"), std::string::npos) << run.err;
  }
}

TEST(FemmChain, SolveRefusesUnknownRegionAndLineOutside) {
  const auto region = run_rheomag("solve '" + kCase + "' --order 1 --integral plunger:force");
  EXPECT_EQ(region.code, 2);
  EXPECT_NE(region.err.find("no region named 'plunger'; the regions are"), std::string::npos)
      << region.err;
  const auto line = run_rheomag("solve '" + kCase + "' --order 1 --line 0,0:5,0");
  EXPECT_EQ(line.code, 2);
  EXPECT_NE(line.err.find("outside the model; the model spans"), std::string::npos) << line.err;
  const auto fine = run_rheomag("solve '" + kCase +
                                "' --order 1 --json --integral gap_top:average_b "
                                "--line 0.0195,-0.01:0.0195,0.01 --points 5");
  ASSERT_EQ(fine.code, 0) << fine.err;
  const auto j = nlohmann::json::parse(fine.out);
  EXPECT_GT(j["integrals"][0]["values"]["b"].get<double>(), 0.1);
  EXPECT_EQ(j["lines"][0]["samples"].size(), 5u);
}

}  // namespace
