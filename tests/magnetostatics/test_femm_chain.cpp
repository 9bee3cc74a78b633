// A FEMM model through the chain (issue 31): `export` writes the model and its gap sidecar,
// `valve`, `damper`, `sweep` and `optimise` run on the model as on the case, and the bad inputs
// exit 2 naming what is wrong.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

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

TEST(FemmChain, ExportedDamperGivesTheCaseForce) {
  // Reference: the same damper from its TOML case. Tolerance 1 % on the force: the .fem is
  // meshed anew from its label sizes (flux linkage within 0.5 % of the case's,
  // FemmExport.AnnularValveRoundTrip), and the gap |B| carries that difference into the
  // yield part of dp and so into F. The [damper] section must come through the sidecar.
  const std::string damper = std::string(RHEOMAG_SOURCE_DIR) + "/cases/damper_piston.toml";
  const fs::path dir = scratch("damper");
  const auto exported = run_rheomag("export '" + damper + "' --fem d.fem", dir);
  ASSERT_EQ(exported.code, 0) << exported.err;
  const auto from_fem = run_rheomag("damper d.fem --velocity 0.1 --json", dir);
  ASSERT_EQ(from_fem.code, 0) << from_fem.err;
  const auto from_case = run_rheomag("damper '" + damper + "' --velocity 0.1 --json");
  ASSERT_EQ(from_case.code, 0) << from_case.err;
  const auto fem = nlohmann::json::parse(from_fem.out), toml = nlohmann::json::parse(from_case.out);
  const double f_fem = fem["points"][0]["force"], f_toml = toml["points"][0]["force"];
  std::printf("damper at 0.1 m/s: F %.6g N from the .fem, %.6g N from the case (%+.3f %%)\n", f_fem,
              f_toml, 100.0 * (f_fem / f_toml - 1.0));
  EXPECT_NEAR(f_fem, f_toml, 0.01 * std::abs(f_toml));
  EXPECT_EQ(fem["gas_force_range"], toml["gas_force_range"]);  // [damper] alone, no field: exact
}

/// The dp_total_Pa column of a sweep's results.csv, one value per design row.
std::vector<double> dp_column(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  int column = -1, k = 0;
  std::stringstream header(line);
  for (std::string cell; std::getline(header, cell, ','); ++k)
    if (cell == "dp_total_Pa") column = k;
  std::vector<double> out;
  while (column >= 0 && std::getline(in, line)) {
    std::stringstream row(line);
    std::string cell;
    for (int c = 0; c <= column; ++c) std::getline(row, cell, ',');
    out.push_back(std::stod(cell));
  }
  return out;
}

TEST(FemmChain, SweepOnExportedValveMatchesTheCaseSweep) {
  // Reference: the same sweep (current x fluid, 4 designs) on the TOML case. Tolerance 1 % on
  // dp, as for `valve` above (the .fem is meshed anew from its label sizes). The fluid axis
  // changes the .fem's fluid blocks to the other library fluid, as it does for the case.
  const fs::path dir = scratch("sweep");
  ASSERT_EQ(run_rheomag("export '" + kCase + "' --fem v.fem", dir).code, 0);
  const std::string axes =
      "[[axis]]\nkey = \"circuit.current\"\nvalues = [0.5, 1.0]\n"
      "[[axis]]\nkey = \"fluid\"\nvalues = [\"MRC-C1L\", \"MRF-132DG\"]\n";
  std::ofstream(dir / "fem.toml") << "[sweep]\nbase = \"v.fem\"\n" << axes;
  std::ofstream(dir / "case.toml") << "[sweep]\nbase = \"" << kCase << "\"\n" << axes;
  const auto fem = run_rheomag("sweep fem.toml --out fem --quiet", dir);
  ASSERT_EQ(fem.code, 0) << fem.err;
  const auto toml = run_rheomag("sweep case.toml --out case --quiet", dir);
  ASSERT_EQ(toml.code, 0) << toml.err;
  const std::vector<double> dp_fem = dp_column(dir / "fem" / "results.csv");
  const std::vector<double> dp_toml = dp_column(dir / "case" / "results.csv");
  ASSERT_EQ(dp_fem.size(), 4u);
  ASSERT_EQ(dp_toml.size(), 4u);
  for (std::size_t k = 0; k < dp_toml.size(); ++k) {
    std::printf("design %zu: dp %.6g Pa from the .fem, %.6g Pa from the case (%+.3f %%)\n", k,
                dp_fem[k], dp_toml[k], 100.0 * (dp_fem[k] / dp_toml[k] - 1.0));
    EXPECT_NEAR(dp_fem[k], dp_toml[k], 0.01 * dp_toml[k]) << "design " << k;
  }
  // The fluid edit took effect on the .fem (MRF-132DG yields at about half of MRC-C1L's stress).
  EXPECT_GT(std::abs(dp_fem[1] / dp_fem[0] - 1.0), 0.2);
}

TEST(FemmChain, GeometryKeysOnAFemAreRefusedByName) {
  const fs::path dir = scratch("keys");
  ASSERT_EQ(run_rheomag("export '" + kCase + "' --fem v.fem", dir).code, 0);
  std::ofstream(dir / "s.toml") << "[sweep]\nbase = \"v.fem\"\n[[axis]]\n"
                                   "key = \"geometry.gap_width\"\nvalues = [1.0]\n";
  const auto sweep = run_rheomag("sweep s.toml --out o", dir);
  EXPECT_EQ(sweep.code, 2);
  EXPECT_NE(sweep.err.find("'geometry.gap_width'"), std::string::npos) << sweep.err;
  EXPECT_NE(sweep.err.find("a .fem model has no named dimensions"), std::string::npos) << sweep.err;
  std::ofstream(dir / "v.toml", std::ios::app)
      << "\n[optimise]\nobjective = \"dp_on\"\nsense = \"maximise\"\nflow = 1e-6\n"
         "[[optimise.variable]]\nkey = \"geometry.turns\"\nlower = 200\nupper = 1000\n";
  const auto optimise = run_rheomag("optimise v.fem --out o --quiet", dir);
  EXPECT_EQ(optimise.code, 2);
  EXPECT_NE(optimise.err.find("v.toml:"), std::string::npos) << optimise.err;  // the sidecar
  EXPECT_NE(optimise.err.find("'geometry.turns'"), std::string::npos) << optimise.err;
  EXPECT_NE(optimise.err.find("a .fem model has no named dimensions"), std::string::npos)
      << optimise.err;
}

// A .fem model's element order is a solver key: `--set solver.order=1` (any command) and the
// sidecar's [solver] order give the mesh and flux linkage of `solve --order 1` exactly; every
// other [solver] key and any order but 1 or 2 exit 2 naming it.
TEST(FemmChain, ElementOrderOfAFemIsASolverKey) {
  const fs::path dir = scratch("order");
  ASSERT_EQ(run_rheomag("export '" + kCase + "' --fem v.fem", dir).code, 0);
  auto solved = [&](const std::string& args) {
    const auto run = run_rheomag("solve v.fem --json " + args, dir);
    EXPECT_EQ(run.code, 0) << args << ": " << run.err;
    return nlohmann::json::parse(run.out.empty() ? "{}" : run.out);
  };
  const auto p1 = solved("--order 1"), p2 = solved("");
  const auto set = solved("--set solver.order=1");
  EXPECT_LT(p1["dofs"].get<int>(), p2["dofs"].get<int>() / 2);  // P2 has the midside nodes
  EXPECT_EQ(set["dofs"], p1["dofs"]);
  EXPECT_EQ(set["flux_linkage"], p1["flux_linkage"]);
  const auto transient = run_rheomag(
      "transient v.fem --current 1 --duration 1ms --steps 2 --json --set solver.order=1", dir);
  ASSERT_EQ(transient.code, 0) << transient.err;
  EXPECT_EQ(nlohmann::json::parse(transient.out)["dofs"], p1["dofs"]);

  std::ofstream(dir / "v.toml", std::ios::app) << "\n[solver]\norder = 1\n";
  const auto sidecar = solved("");
  EXPECT_EQ(sidecar["dofs"], p1["dofs"]);
  EXPECT_EQ(sidecar["flux_linkage"], p1["flux_linkage"]);

  const auto three = run_rheomag("solve v.fem --set solver.order=3", dir);
  EXPECT_EQ(three.code, 2);
  EXPECT_NE(three.err.find("'solver.order': expected 1 or 2"), std::string::npos) << three.err;
  const auto other = run_rheomag("solve v.fem --set solver.outer_boundary=open", dir);
  EXPECT_EQ(other.code, 2);
  EXPECT_NE(other.err.find("takes 'solver.order' (1 or 2) only"), std::string::npos) << other.err;
  std::ofstream(dir / "v.toml", std::ios::app) << "min_gap_elements = 3\n";
  const auto unknown = run_rheomag("solve v.fem", dir);
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.err.find("v.toml"), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("min_gap_elements"), std::string::npos) << unknown.err;
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

TEST(FemmChain, ModelWithoutSidecarNamesTheFileThatWouldFixIt) {
  // Issue 34: an error about a missing sidecar says which file would fix it.
  const fs::path dir = scratch("no_sidecar");
  ASSERT_EQ(run_rheomag("export '" + kCase + "' --fem v.fem", dir).code, 0);
  fs::remove(dir / "v.toml");
  const auto run = run_rheomag("valve v.fem --flow 1e-6", dir);
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("v.toml"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("[[fem.gap]]"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("rheomag export CASE --fem"), std::string::npos) << run.err;
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
