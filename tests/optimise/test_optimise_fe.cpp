// FE-in-the-loop optimisation on a coarse P1 annular valve: gradient consistency on the morphed
// mesh, constraints respected at the written optimum (re-solved from the file), infeasible
// specifications reported, bad input rejected.

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "optimise/evaluate.hpp"
#include "optimise/run.hpp"
#include "optimise/spec.hpp"
#include "optimise_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using namespace rheomag;
using optimise_fixture::kBase;
using optimise_fixture::kTimeAndLength;
using optimise_fixture::kTwoVariables;
using optimise_fixture::make_case;
using optimise_fixture::TempDir;

// Central differences of dp_on in neck_radius on the morphed mesh at three steps (0.2, 0.05,
// 0.0125 mm): with a smooth objective the O(h^2) truncation error makes successive estimates
// agree to well under 2 %, and all designs share one mesh (no re-meshing noise).
TEST(OptimiseFe, GradientIsConsistentAcrossStepSizesOnTheMorphedMesh) {
  const auto c = make_case(kTwoVariables);
  optimise::OptimiseEvaluator evaluator(c, optimise::read_optimise_spec(c));
  const double r0 = 10.5, p0 = 5.0;
  std::vector<double> slopes;
  for (double h : {0.2, 0.05, 0.0125}) {
    const double up = evaluator.evaluate({r0 + h, p0})[design::Quantity::dp_on];
    const double down = evaluator.evaluate({r0 - h, p0})[design::Quantity::dp_on];
    slopes.push_back((up - down) / (2.0 * h));
  }
  EXPECT_EQ(evaluator.meshes(), 1);
  EXPECT_EQ(evaluator.fe_solves(), 6);
  ASSERT_NE(slopes[2], 0.0);
  EXPECT_NEAR(slopes[0] / slopes[2], 1.0, 0.02) << slopes[0] << " " << slopes[2];
  EXPECT_NEAR(slopes[1] / slopes[2], 1.0, 0.02) << slopes[1] << " " << slopes[2];
}

// A finite-difference neighbour's static solve starts from its centre's field (the same mesh
// topology): fewer Newton steps, the same quantities to Newton's tolerance. Reference: the same
// neighbour solved from A = 0 on the same morphed mesh (a second evaluator, its centre first);
// tolerance 1e-7 relative (Newton stops at a 1e-8 relative residual). The centre itself is
// solved from A = 0 whatever came before, so its values do not depend on the path.
TEST(OptimiseFe, NeighbourStartsFromItsCentresFieldInFewerNewtonSteps) {
  const auto c = make_case(kTwoVariables);
  const std::vector<double> centre{10.5, 5.0}, neighbour{10.5 + 0.01, 5.0};
  optimise::OptimiseEvaluator warm(c, optimise::read_optimise_spec(c));
  optimise::OptimiseEvaluator cold(c, optimise::read_optimise_spec(c));
  warm.evaluate(centre);
  const int centre_steps = warm.last_field().solution.newton.iterations;
  const auto q_warm = warm.evaluate(neighbour, true);
  const int warm_steps = warm.last_field().solution.newton.iterations;
  cold.evaluate(centre);
  const auto q_cold = cold.evaluate(neighbour);  // not a neighbour: from A = 0
  const int cold_steps = cold.last_field().solution.newton.iterations;
  std::printf("Newton steps: centre %d, neighbour from its centre %d, from A = 0 %d\n",
              centre_steps, warm_steps, cold_steps);
  EXPECT_LT(warm_steps, cold_steps);
  EXPECT_EQ(warm.meshes(), 1);
  EXPECT_EQ(cold.meshes(), 1);
  for (design::Quantity q :
       {design::Quantity::dp_on, design::Quantity::b_gap, design::Quantity::inductance})
    EXPECT_NEAR(q_warm[q] / q_cold[q], 1.0, 1e-7) << design::quantity_name(q);
  // Back at the centre (a morph of the first mesh), from A = 0 after either path: the same
  // values bit for bit.
  EXPECT_EQ(warm.evaluate(centre)[design::Quantity::dp_on],
            cold.evaluate(centre)[design::Quantity::dp_on]);
}

// Optimise with L/R and length constraints; the written case is re-loaded and re-evaluated on a
// fresh mesh (as `rheomag solve` does): every constraint holds there within the feasibility
// tolerance kFeasibilityTolerance (0.1 % of the limit).
TEST(OptimiseFe, WrittenOptimumRespectsEveryConstraint) {
  const auto c = make_case(kTwoVariables + kTimeAndLength);
  const TempDir dir("constraints");
  const auto r = optimise_fixture::run(c, dir);
  ASSERT_TRUE(r.optimal.feasible) << optimise::format_summary(r);
  ASSERT_TRUE(fs::exists(r.case_file));
  ASSERT_TRUE(fs::exists(r.history_file));
  ASSERT_TRUE(fs::exists(r.vtu_file));

  const auto reloaded = cases::load_case(r.case_file);
  const auto reloaded_spec = optimise::read_optimise_spec(reloaded);
  optimise::OptimiseEvaluator check(reloaded, reloaded_spec);
  std::vector<double> x;
  for (const auto& v : reloaded_spec.variables) x.push_back(v.initial);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_DOUBLE_EQ(x[i], r.optimal.x[i]);
  const auto q = check.evaluate(x);
  for (const auto& k : reloaded_spec.constraints) {
    const double value = q[k.quantity];
    if (std::isfinite(k.upper)) {
      EXPECT_LE(value, k.upper * (1.0 + optimise::kFeasibilityTolerance))
          << design::quantity_name(k.quantity);
    }
    if (std::isfinite(k.lower)) {
      EXPECT_GE(value, k.lower * (1.0 - optimise::kFeasibilityTolerance))
          << design::quantity_name(k.quantity);
    }
  }
}

// The optimum against a dense 9 x 9 grid over the same bounds, each grid design on a fresh mesh
// (as `rheomag sweep` evaluates it): the optimum is at least as good as the best feasible grid
// design (within 0.5 %: the grid point can sit on the constraint boundary only approximately, and
// fresh meshes carry the coarse mesh's discretisation noise) and takes fewer FE solves than the
// grid's 81.
TEST(OptimiseFe, OptimumBeatsTheBestOfADenseGridAtFewerSolves) {
  const auto c = make_case(kTwoVariables + kTimeAndLength);
  const TempDir dir("grid");
  const auto r = optimise_fixture::run(c, dir);
  ASSERT_TRUE(r.optimal.feasible) << optimise::format_summary(r);

  const auto s = optimise::read_optimise_spec(c);
  optimise::OptimiseEvaluator grid(c, s);
  double best = -INFINITY;
  const int n = 9;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x0 =
          s.variables[0].lower + (s.variables[0].upper - s.variables[0].lower) * i / (n - 1);
      const double x1 =
          s.variables[1].lower + (s.variables[1].upper - s.variables[1].lower) * j / (n - 1);
      grid.remesh_next();
      const auto q = grid.evaluate({x0, x1});
      if (optimise::report_design(s, {x0, x1}, q).feasible)
        best = std::max(best, q[design::Quantity::dp_on]);
    }
  ASSERT_TRUE(std::isfinite(best));
  EXPECT_GE(r.optimal.objective, best * (1.0 - 0.005)) << r.optimal.objective << " vs " << best;
  EXPECT_LT(r.fe_solves, n * n);
  std::printf("optimum dp_on %.6g Pa in %d FE solves; best of %d grid designs %.6g Pa\n",
              r.optimal.objective, r.fe_solves, n * n, best);
}

// Turns are varied continuously, then rounded (nearest, down, up; re-checked on a fresh mesh):
// the written optimum has whole turns and still meets L/R <= 50 ms.
TEST(OptimiseFe, TurnsAreRoundedAndReChecked) {
  const std::string spec = kTwoVariables + R"(
[[optimise.variable]]
key = "geometry.turns"
lower = 300
upper = 700
)" + optimise_fixture::kTimeConstant;
  const auto c = make_case(spec);
  const TempDir dir("turns");
  const auto r = optimise_fixture::run(c, dir);
  ASSERT_TRUE(r.optimal.feasible) << optimise::format_summary(r);
  const double turns = r.optimal.x[2];
  EXPECT_EQ(turns, std::round(turns));
  const auto reloaded = cases::load_case(r.case_file);
  EXPECT_EQ(reloaded.table["geometry"]["turns"].value<double>().value_or(-1.0), turns);
  EXPECT_LE(r.optimal.quantities[design::Quantity::time_constant],
            0.05 * (1.0 + optimise::kFeasibilityTolerance));
}

// L/R at most 1 ms and dp_on at least 50 MPa cannot both hold in these bounds: the run ends
// infeasible and names both constraints.
TEST(OptimiseFe, InfeasibleSpecificationNamesTheConflictingConstraints) {
  const std::string spec = kTwoVariables + R"(
[[optimise.constraint]]
quantity = "time_constant"
max = 0.001
[[optimise.constraint]]
quantity = "dp_on"
min = 5e7
)";
  const auto c = make_case(spec);
  const TempDir dir("infeasible");
  const auto r = optimise_fixture::run(c, dir);
  EXPECT_FALSE(r.optimal.feasible);
  std::string all;
  for (const auto& text : r.conflicts) all += text + "\n";
  EXPECT_NE(all.find("time_constant"), std::string::npos) << all;
  EXPECT_NE(all.find("dp_on"), std::string::npos) << all;
  EXPECT_NE(optimise::format_summary(r).find("No feasible design"), std::string::npos);
}

using optimise_fixture::input_error;

TEST(OptimiseFe, BadInputIsAnInputErrorNamingTheKey) {
  const std::string head = "[optimise]\nflow = 1e-6\n";
  // Bounds reversed.
  EXPECT_NE(input_error(head + "[[optimise.variable]]\nkey = \"geometry.neck_radius\"\n"
                               "lower = 12.0\nupper = 8.0\n")
                .find("bounds reversed"),
            std::string::npos);
  // Not a case key: the closest key is suggested.
  EXPECT_NE(input_error(head + "[[optimise.variable]]\nkey = \"geometry.neck_radios\"\n"
                               "lower = 8.0\nupper = 12.0\n")
                .find("did you mean 'geometry.neck_radius'"),
            std::string::npos);
  // A dimension bound that is not physical.
  EXPECT_NE(input_error(head + "[[optimise.variable]]\nkey = \"geometry.pole_length\"\n"
                               "lower = -1.0\nupper = 8.0\n")
                .find("> 0"),
            std::string::npos);
  // No on state: the coil model's message named no file or key.
  EXPECT_NE(input_error("[optimise]\nflow = 1e-6\ncurrent = 0.0\n[[optimise.variable]]\n"
                        "key = \"geometry.neck_radius\"\nlower = 8.0\nupper = 12.0\n")
                .find("coarse_annular.toml:23: optimise.current: expected a non-zero on-state "
                      "coil current (A), got 0"),
            std::string::npos);
  // Unknown constraint quantity.
  EXPECT_NE(input_error(head + "[[optimise.variable]]\nkey = \"geometry.neck_radius\"\n"
                               "lower = 8.0\nupper = 12.0\n[[optimise.constraint]]\n"
                               "quantity = \"time_constnt\"\nmax = 0.03\n")
                .find("did you mean \"time_constant\""),
            std::string::npos);
}

// The CLI exits 2 on bad input and prints nothing on stdout.
TEST(OptimiseFe, CliExitsTwoOnBadInput) {
  const TempDir temp("cli");
  const fs::path& dir = temp.path;
  const fs::path file = dir / "bad.toml";
  std::ofstream(file) << kBase
                      << "[optimise]\nflow = 1e-6\n[[optimise.variable]]\n"
                         "key = \"geometry.neck_radius\"\nlower = 12.0\nupper = 8.0\n";
  const std::string command = std::string(RHEOMAG_BINARY) + " optimise " + file.string() +
                              " --out " + dir.string() + " --json > " + (dir / "out.txt").string() +
                              " 2>/dev/null";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_EQ(fs::file_size(dir / "out.txt"), 0u);
}

}  // namespace
