// `rheomag solve CASE --3d` end to end: the issue's JSON keys (the 2D ones plus dimension,
// tetrahedra and 36 sectors of B_avg_theta per gap), the gap average against `rheomag solve` in
// 2D on the same case, and a bad --mesher name as exit 2 naming the option.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli_run.hpp"

namespace {

const std::string kValve = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";

}  // namespace

// Reference: the 2D solve of the same case (the swept wedge is within 1 % of it in the gap
// average, test_swept_mesh.cpp; here at the CLI's default swept settings, 2 %).
TEST(Solve3dCli, SweptWedgePrintsTheIssuesKeysAndThe2dGapField) {
  const auto three =
      rheomag::cli_test::run_rheomag("solve '" + kValve + "' --3d --mesher swept --json");
  ASSERT_EQ(three.code, 0) << three.err;
  const auto json3 = nlohmann::json::parse(three.out);
  for (const char* key : {"gaps", "circuits", "flux_linkage", "inductance", "energy", "dofs",
                          "elements", "newton_iterations", "seconds", "dimension", "tetrahedra"})
    EXPECT_TRUE(json3.contains(key)) << key;
  EXPECT_EQ(json3["dimension"].get<int>(), 3);
  const auto two = rheomag::cli_test::run_rheomag("solve '" + kValve + "' --json");
  ASSERT_EQ(two.code, 0) << two.err;
  const auto json2 = nlohmann::json::parse(two.out);
  ASSERT_EQ(json3["gaps"].size(), json2["gaps"].size());
  for (std::size_t g = 0; g < json3["gaps"].size(); ++g) {
    const auto& gap = json3["gaps"][g];
    ASSERT_EQ(gap["B_avg_theta"].size(), 36u) << gap["name"];
    const double b2 = json2["gaps"][g]["B_avg"].get<double>();
    EXPECT_NEAR(gap["B_avg"].get<double>(), b2, 0.02 * b2) << gap["name"];
  }
}

TEST(Solve3dCli, UnknownMesherIsExitTwoNamingTheOption) {
  const auto run = rheomag::cli_test::run_rheomag("solve '" + kValve + "' --3d --mesher voxel");
  EXPECT_EQ(run.code, 2) << run.err;
  EXPECT_NE(run.err.find("--mesher"), std::string::npos) << run.err;
}
