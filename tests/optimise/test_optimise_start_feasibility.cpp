// Issue 34: a starting design that breaks its own constraint (cases/optimise_annular.toml: L/R
// 71 ms against a 30 ms limit) was not reported, so "max dp_on: 1.69e6 -> 708550" read as if the
// optimiser had made the valve worse. The report now names the start's broken constraints with
// value and limit (text and JSON) and words the objective change accordingly. Reference: the
// numbers put in; no FE solve.

#include <gtest/gtest.h>

#include <string>

#include "optimise/report.hpp"
#include "optimise/run.hpp"

namespace {

using namespace rheomag;

/// A result with the shipped case's numbers: maximise dp_on subject to time_constant <= 30 ms;
/// start 1.69e6 Pa at 71 ms (infeasible), optimum 708550 Pa at 30 ms.
optimise::OptimiseResult infeasible_start() {
  optimise::OptimiseResult r;
  r.spec.objective = "dp_on";
  r.spec.maximise = true;
  r.spec.terms = {{design::Quantity::dp_on, 1.0, 1.0}};
  optimise::Constraint c;
  c.quantity = design::Quantity::time_constant;
  c.upper = 0.03;
  r.spec.constraints = {c};
  design::Quantities start, optimum;
  start[design::Quantity::dp_on] = 1.69e6;
  start[design::Quantity::time_constant] = 0.0712;
  optimum[design::Quantity::dp_on] = 708550;
  optimum[design::Quantity::time_constant] = 0.03;
  r.initial = optimise::report_design(r.spec, {}, start);
  r.optimal = optimise::report_design(r.spec, {}, optimum);
  r.status = "Solve_Succeeded";
  r.converged = true;
  return r;
}

TEST(OptimiseStartFeasibility, InfeasibleStartIsReportedWithValueAndLimit) {
  const optimise::OptimiseResult r = infeasible_start();
  ASSERT_FALSE(r.initial.feasible);
  ASSERT_TRUE(r.optimal.feasible);
  const std::string text = optimise::format_summary(r);
  EXPECT_NE(text.find("starting design (the case as written): INFEASIBLE, it breaks\n"
                      "  time_constant = 0.0712 s > max 0.03 s (2.37 x the limit)\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("feasible optimum; objective max dp_on: 1.69e+06 Pa at the infeasible "
                      "start -> 708550 Pa at the feasible optimum (not a loss: the start's value "
                      "needs time_constant <= 0.03 broken; no feasible design reaches it)"),
            std::string::npos)
      << text;
  const nlohmann::json v = optimise::violations_json(r.initial);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_EQ(v[0]["quantity"], "time_constant");
  EXPECT_EQ(v[0]["bound"], "max");
  EXPECT_EQ(v[0]["unit"], "s");
  EXPECT_DOUBLE_EQ(v[0]["value"].get<double>(), 0.0712);
  EXPECT_DOUBLE_EQ(v[0]["limit"].get<double>(), 0.03);
  EXPECT_TRUE(optimise::violations_json(r.optimal).empty());
}

TEST(OptimiseStartFeasibility, FeasibleStartSaysSo) {
  optimise::OptimiseResult r = infeasible_start();
  design::Quantities start;
  start[design::Quantity::dp_on] = 5e5;
  start[design::Quantity::time_constant] = 0.02;
  r.initial = optimise::report_design(r.spec, {}, start);
  const std::string text = optimise::format_summary(r);
  EXPECT_NE(text.find("starting design (the case as written): feasible\n"), std::string::npos)
      << text;
  EXPECT_NE(text.find("feasible optimum; objective max dp_on: 500000 Pa -> 708550 Pa\n"),
            std::string::npos)
      << text;
}

}  // namespace
