// The valve chain on the bundled paper-000 annular valve case, and `rheomag valve --json`.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "fluid/newtonian.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "tests/cli_run.hpp"
#include "valve/valve_chain.hpp"

using namespace rheomag;

namespace {

const std::string kCase = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";

valve::ValveChain& annular_chain() {
  static valve::ValveChain chain = [] {
    valve::ValveOptions options;
    options.wire = "AWG 24";
    return valve::ValveChain(cases::load_case(kCase), options);
  }();
  return chain;
}

}  // namespace

// Reference: with no current the MRC-C1L table gives tau_y(0) = 0, so each pole gap is a
// Newtonian annulus (h = 1 mm, R = 19.5 mm, L = 5 mm per pole, paper 000 / case file):
// dp = 2 x annulus Poiseuille within 1e-9, and no yield part.
TEST(ValveChain, FluxFreeGapsGiveViscousDropOnly) {
  const auto points = annular_chain().evaluate({0.0}, {2e-6});
  ASSERT_EQ(points.size(), 1u);
  ASSERT_EQ(points[0].segments.size(), 2u);
  const double ref = 2.0 * fluid::annulus_poiseuille_dp(fluid::AnnulusGeometry{1e-3, 19.5e-3, 5e-3},
                                                        annular_chain().fluid().viscosity, 2e-6);
  EXPECT_NEAR(points[0].dp_total / ref, 1.0, 1e-9);
  EXPECT_EQ(points[0].dp_yield, 0.0);
}

// Physical ordering: more current -> more field -> more pressure drop (B below saturation of
// the yield-stress table); flow changes dp little at Bi >> 1. Each dp_total is the sum of its
// segments.
TEST(ValveChain, PressureDropGrowsWithCurrent) {
  const auto points = annular_chain().evaluate({0.25, 0.5, 1.0}, {1e-6, 1e-5});
  ASSERT_EQ(points.size(), 6u);
  for (std::size_t i = 2; i < points.size(); i += 2)
    EXPECT_GT(points[i].dp_total, points[i - 2].dp_total);
  for (const auto& p : points) {
    double sum = 0.0;
    for (const auto& s : p.segments) sum += s.drop.integrated.dp;
    EXPECT_NEAR(p.dp_total, sum, 1e-9 * sum);
    EXPECT_GT(p.segments[0].b_average, 0.0);
  }
  EXPECT_GT(points[1].dp_total, points[0].dp_total);  // higher flow, same current
}

// Reference: the case file's header (600 turns AWG 24, mean turn 2 pi 15 mm: ~4.8 Ohm); the
// mesh-derived winding must give R within 5 % of 4.76 Ohm, and L/R = L / R exactly.
TEST(ValveChain, CoilFromTheCase) {
  auto& chain = annular_chain();
  EXPECT_EQ(chain.turns(), 600.0);
  const auto coil = chain.coil(1.0, 0.3);
  EXPECT_NEAR(coil.resistance / 4.76, 1.0, 0.05);
  EXPECT_NEAR(coil.time_constant, 0.3 / coil.resistance, 1e-15);
  EXPECT_NEAR(coil.power, coil.resistance, 1e-12);
}

TEST(ValveChain, BadInputThrows) {
  EXPECT_THROW(annular_chain().evaluate({1.0}, {-1e-6}), InputError);
  EXPECT_THROW(annular_chain().evaluate({}, {1e-6}), InputError);
}

// The CLI: keys of the fixed interface and values equal to the library's.
TEST(CmdValve, JsonKeysAndValues) {
  const auto run = cli_test::run_rheomag(std::string("valve ") + kCase +
                                         " --current 0,1 --flow 1e-6 --wire 'AWG 24' --json");
  ASSERT_EQ(run.code, 0) << run.err;
  const std::string& out = run.out;
  const auto json = nlohmann::json::parse(out);
  ASSERT_EQ(json["points"].size(), 2u);
  for (const char* key : {"current", "flow", "dp_total", "dp_yield", "dp_viscous", "segments"})
    EXPECT_TRUE(json["points"][0].contains(key)) << key;
  for (const char* key : {"turns", "resistance", "inductance", "time_constant", "power"})
    EXPECT_TRUE(json["coil"].contains(key)) << key;
  const auto points = annular_chain().evaluate({1.0}, {1e-6});
  EXPECT_NEAR(json["points"][1]["dp_total"].get<double>() / points[0].dp_total, 1.0, 1e-9);
  EXPECT_EQ(json["points"][0]["dp_yield"].get<double>(), 0.0);
  const auto bad = cli_test::run_rheomag("valve " + std::string(RHEOMAG_SOURCE_DIR) +
                                         "/cases/radial_valve.toml --current 1");  // no flow rate
  EXPECT_EQ(bad.code, 2);
}

// Issue 29: `valve --json` gave each gap's mean B only. Each gap segment now carries the B(s)
// the yield drop was integrated over; reference: its mean over the gap's 5 mm pole length
// (cases/annular_valve.toml; trapezoids between the samples, the end samples held to the gap's
// ends, as fluid::integrate_samples integrates) equals the segment's b_average to 1e-12, the
// samples lie inside the gap, and the field is non-zero at 1 A.
TEST(CmdValve, GapProfileAveragesToTheSegmentsMeanB) {
  const auto run =
      cli_test::run_rheomag(std::string("valve ") + kCase + " --current 1 --flow 1e-6 --json");
  ASSERT_EQ(run.code, 0) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  int gaps = 0;
  for (const auto& segment : json["points"][0]["segments"]) {
    if (!segment.contains("profile")) continue;
    ++gaps;
    const std::vector<double> s = segment["profile"]["s"], b = segment["profile"]["B_n"];
    ASSERT_EQ(s.size(), b.size());
    ASSERT_GE(s.size(), 2u);
    const double length = 5e-3;
    EXPECT_GE(s.front(), 0.0) << segment["name"];
    EXPECT_LE(s.back(), length) << segment["name"];
    double integral = b.front() * s.front() + b.back() * (length - s.back());
    for (std::size_t k = 1; k < s.size(); ++k)
      integral += 0.5 * (b[k] + b[k - 1]) * (s[k] - s[k - 1]);
    const double mean = integral / length;
    EXPECT_NEAR(mean, segment["b_average"].get<double>(), 1e-12 * mean) << segment["name"];
    EXPECT_GT(mean, 0.5) << segment["name"];
  }
  EXPECT_EQ(gaps, 2) << "both pole gaps carry a profile";
}

// Issue 36: `--temperature -250` printed R = -0.291 Ohm with exit 0; the option and the
// `[valve] temperature` key are read in the copper model's domain, refused with exit 2 naming it.
TEST(CmdValve, TemperatureOutsideTheCopperModelIsExit2) {
  const auto cold = cli_test::run_rheomag(std::string("valve ") + kCase + " --temperature -250");
  EXPECT_EQ(cold.code, 2);
  EXPECT_NE(cold.err.find("--temperature: expected a number in [-200, 250] (deg C), got -250"),
            std::string::npos)
      << cold.err;
  EXPECT_EQ(cold.out, "");
  const auto dir = std::filesystem::temp_directory_path() / "rheomag_test_valve_temperature";
  std::filesystem::create_directories(dir);
  std::ifstream in(kCase);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  const std::size_t at = text.find("[valve]");
  ASSERT_NE(at, std::string::npos);
  text.insert(text.find('\n', at) + 1, "temperature = 300.0\n");
  std::ofstream(dir / "hot.toml") << text;
  const auto hot = cli_test::run_rheomag("valve '" + (dir / "hot.toml").string() + "'");
  EXPECT_EQ(hot.code, 2);
  EXPECT_NE(hot.err.find("valve.temperature: expected a number in [-200, 250] (deg C), got 300"),
            std::string::npos)
      << hot.err;
  std::filesystem::remove_all(dir);
}

// L(I) table of `rheomag valve --json`. References: lambda = L I by definition of the secant
// inductance; at I = 0 the secant is reported as the incremental one; the core neck saturates
// towards 1 A, so lambda(I) is concave there and dlambda/dI < lambda/I. The values must equal
// MagnetostaticSolver::sweep on the same case within Newton's tolerance (1e-6 relative; the
// sweep warm-starts each current, the valve starts each from A = 0).
TEST(CmdValve, InductanceTable) {
  const auto run = cli_test::run_rheomag(std::string("valve ") + kCase +
                                         " --current 0,0.5,1 --flow 1e-6 --json");
  ASSERT_EQ(run.code, 0) << run.err;
  const std::string& out = run.out;
  const auto table = nlohmann::json::parse(out)["coil"]["inductance_table"];
  ASSERT_EQ(table.size(), 3u);
  auto solved = magnetostatics::solve_problem(cases::load_case(kCase).problem);
  const auto sweep = solved.solver->sweep(0, {0.0, 0.5, 1.0});
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& row = table[i];
    const double current = row["current"].get<double>();
    EXPECT_EQ(current, sweep[i].current);
    EXPECT_NEAR(row["flux_linkage"].get<double>(), row["inductance"].get<double>() * current,
                1e-12);
    EXPECT_NEAR(row["inductance"].get<double>() / sweep[i].secant_inductance, 1.0, 1e-6);
    EXPECT_NEAR(row["incremental_inductance"].get<double>() / sweep[i].incremental_inductance, 1.0,
                1e-6);
  }
  EXPECT_EQ(table[0]["inductance"].get<double>(), table[0]["incremental_inductance"].get<double>());
  EXPECT_LT(table[2]["incremental_inductance"].get<double>(), table[2]["inductance"].get<double>());
}
