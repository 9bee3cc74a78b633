// Discrete choices by enumeration, weighted-sum objectives and the Pareto front on the coarse
// FE annular valve (optimise_fixture.hpp).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
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
using optimise_fixture::make_case;
using optimise_fixture::TempDir;

// Neck radius only, L/R <= 50 ms: a one-variable problem per combination.
const std::string kNeck = R"(
[optimise]
objective = "dp_on"
current = 1.0
flow = 6.91e-6
max_iterations = 10
enumerate = { fluid = ["MRF-132DG", "MRF-140CG"], "geometry.disk_material" = ["AISI 1010"] }
[[optimise.variable]]
key = "geometry.neck_radius"
lower = 8.0
upper = 12.5
)" + optimise_fixture::kTimeConstant;

// Two fluids: each combination gets its own continuous optimum; the reported choice is the one
// with the largest feasible dp_on; the written case names that fluid and, re-evaluated on a fresh
// mesh (as `rheomag solve` does), gives the reported dp_on (same mesh, same solve: 1e-9).
// MRF-140CG has the higher yield stress at every B of its datasheet curve, so it must win.
TEST(OptimiseChoices, EnumerationPicksTheBestFeasibleCombination) {
  const auto c = make_case(kNeck);
  const TempDir dir("enumerate");
  const auto r = optimise_fixture::run(c, dir);
  ASSERT_EQ(r.combinations.size(), 2u);
  // Every FE solve counted: the case as written (1) plus each combination's.
  EXPECT_EQ(r.fe_solves, 1 + r.combinations[0].fe_solves + r.combinations[1].fe_solves);
  for (const auto& m : r.combinations) {
    EXPECT_TRUE(m.optimal.feasible) << optimise::format_summary(r);
    EXPECT_GT(m.fe_solves, 0);
    ASSERT_EQ(m.choice.size(), 2u);
  }
  const auto& best = r.combinations[r.chosen];
  for (const auto& m : r.combinations) EXPECT_GE(best.optimal.objective, m.optimal.objective);
  EXPECT_EQ(best.choice[0].second, "MRF-140CG");
  EXPECT_DOUBLE_EQ(r.optimal.objective, best.optimal.objective);
  EXPECT_NE(optimise::format_summary(r).find("<- best"), std::string::npos);

  const auto reloaded = cases::load_case(r.case_file);
  EXPECT_EQ(reloaded.table["case"]["fluid"].value_or(std::string()), "MRF-140CG");
  EXPECT_EQ(reloaded.table["geometry"]["fluid_material"].value_or(std::string()), "MRF-140CG");
  auto spec = optimise::read_optimise_spec(reloaded);
  spec.choices.clear();
  optimise::OptimiseEvaluator check(reloaded, spec);
  const double dp = check.evaluate(r.optimal.x)[design::Quantity::dp_on];
  EXPECT_NEAR(dp, r.optimal.objective, 1e-9 * dp);
}

using optimise_fixture::input_error;

const std::string kHead =
    "[optimise]\nflow = 1e-6\n[[optimise.variable]]\nkey = \"geometry.neck_radius\"\n"
    "lower = 8.0\nupper = 12.0\n";

TEST(OptimiseChoices, WeightedSumAndParetoAreReadAndChecked) {
  const auto spec = optimise::read_optimise_spec(
      make_case("[optimise]\nflow = 1e-6\nobjective = { dp_on = 1.0, power = -0.5 }\n"
                "[optimise.pareto]\nquantity = \"time_constant\"\nsense = \"minimise\"\n"
                "points = 4\n[[optimise.variable]]\nkey = \"geometry.neck_radius\"\n"
                "lower = 8.0\nupper = 12.0\n"));
  ASSERT_EQ(spec.terms.size(), 2u);
  EXPECT_EQ(spec.objective, "weighted_sum");
  EXPECT_EQ(spec.terms[1].quantity, design::Quantity::power);
  EXPECT_EQ(spec.terms[1].weight, -0.5);
  ASSERT_TRUE(spec.pareto);
  EXPECT_EQ(spec.pareto->points, 4);
  EXPECT_FALSE(spec.pareto->maximise);
  // Unknown quantity in a weighted sum: named, with the closest and the list of valid names.
  const std::string unknown =
      input_error("[optimise]\nflow = 1e-6\nobjective = { dp_onn = 1.0, power = -0.5 }\n");
  EXPECT_NE(unknown.find("did you mean \"dp_on\""), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("rise_time"), std::string::npos) << unknown;
  // Enumeration of a material that does not exist.
  const std::string material = input_error(
      "[optimise]\nflow = 1e-6\nenumerate = { \"geometry.core_material\" = [\"AISI 9999\"] }\n"
      "[[optimise.variable]]\nkey = \"geometry.neck_radius\"\nlower = 8.0\nupper = 12.0\n");
  EXPECT_NE(material.find("AISI 9999"), std::string::npos) << material;
  // Pareto without a sense, or on the objective itself.
  EXPECT_NE(input_error(kHead + "[optimise.pareto]\nquantity = \"power\"\n").find("sense"),
            std::string::npos);
  EXPECT_NE(input_error(kHead + "[optimise.pareto]\nquantity = \"dp_on\"\nsense = \"minimise\"\n")
                .find("must differ"),
            std::string::npos);
}

// The shipped examples read: [optimise] spec and evaluator set up (no FE solve), the variables'
// starts are the cases' own values inside their bounds.
TEST(OptimiseChoices, ShippedCasesAreValid) {
  for (const char* name :
       {"optimise_annular.toml", "optimise_meandering.toml", "optimise_annular_pareto.toml",
        "optimise_annular_rise.toml", "optimise_annular_response.toml"}) {
    const auto c = cases::load_case(fs::path(RHEOMAG_SOURCE_DIR) / "cases" / name);
    const auto spec = optimise::read_optimise_spec(c);
    EXPECT_NO_THROW(optimise::OptimiseEvaluator(c, spec)) << name;
    EXPECT_GE(spec.variables.size(), 2u) << name;  // the response example has 2 (its header)
    EXPECT_EQ(spec.objective, "dp_on") << name;
  }
}

// FE Pareto front, dp_on against L/R on the neck radius (3 levels): dp_on falls monotonically as
// the L/R limit tightens, every level meets its own limit (feasibility tolerance 0.1 %), the end
// levels are the two single-objective optima, and pareto.csv has one row per level.
TEST(OptimiseChoices, FeParetoFrontIsMonotoneAndWritten) {
  const auto c = make_case(R"(
[optimise]
objective = "dp_on"
flow = 6.91e-6
max_iterations = 10
[optimise.pareto]
quantity = "time_constant"
sense = "minimise"
points = 3
[[optimise.variable]]
key = "geometry.neck_radius"
lower = 8.0
upper = 12.5
)");
  const TempDir dir("pareto");
  const auto r = optimise_fixture::run(c, dir);
  ASSERT_TRUE(r.pareto);
  const auto& points = r.pareto->points;
  ASSERT_EQ(points.size(), 3u);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double tau = points[k].design.quantities[design::Quantity::time_constant];
    EXPECT_LE(tau, points[k].epsilon * (1.0 + optimise::kFeasibilityTolerance)) << k;
    if (k > 0) {
      EXPECT_LE(points[k].design.objective, points[k - 1].design.objective) << k;
    }
  }
  const double tau_min = r.pareto->second_alone.quantities[design::Quantity::time_constant];
  EXPECT_NEAR(points.back().epsilon, tau_min, 1e-12);
  ASSERT_FALSE(r.pareto_files.empty());
  std::ifstream csv(r.pareto_files[0]);
  std::stringstream text;
  text << csv.rdbuf();
  const std::string s = text.str();
  EXPECT_EQ(std::count(s.begin(), s.end(), '\n'), 4);
}

}  // namespace
