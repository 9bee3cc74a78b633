// Issue 36 on `rheomag transient`: no wrong answer with exit 0 (equal steps that do not resolve
// the response are said, with the error measured; a tiny drive is solved, not printed as
// zeros), no endless run (an absurd resistance is refused with the largest it allows), and the
// progress line gives the time left.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli_run.hpp"

namespace {

using rheomag::cli_test::run_rheomag;

const std::string kValve = "'" + std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml'";

/// `rheomag transient VALVE ARGS --json --quiet`, parsed; fails the test on a non-zero exit.
nlohmann::json transient_json(const std::string& arguments) {
  const auto run = run_rheomag("transient " + kValve + " " + arguments + " --json --quiet");
  EXPECT_EQ(run.code, 0) << run.err;
  return run.code == 0 ? nlohmann::json::parse(run.out) : nlohmann::json();
}

TEST(TransientBounds, UnresolvedEqualStepsAreWarnedWithTheirMeasuredError) {
  // 4 equal steps over 50 ms of the annular valve's 1 A current step. Reference for the error
  // the warning states: the same step in 256 equal steps (64 per coarse step), compared at the
  // coarse times. The half-step (Richardson) measurement may over-estimate, never under by more
  // than its asymptotic slack: it must lie within [1, 3] times the reference error (measured
  // 2.36 % against 1.38 %). With 256 steps the run is resolved and says nothing.
  const nlohmann::json coarse = transient_json("--current 1 --duration 0.05 --steps 4");
  const nlohmann::json fine = transient_json("--current 1 --duration 0.05 --steps 256");
  ASSERT_FALSE(coarse.is_null() || fine.is_null());
  const int steps = coarse["steps"];
  const std::size_t head = coarse["time"].size() - steps;
  const std::size_t fine_head = fine["time"].size() - static_cast<int>(fine["steps"]);
  const double change =
      std::abs(double(coarse["final_flux_linkage"]) - double(coarse["flux_linkage"][0]));
  double reference = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double a = coarse["flux_linkage"][head + k];
    const double b = fine["flux_linkage"][fine_head + 64 * (k + 1) - 1];
    reference = std::max(reference, std::abs(a - b) / change);
  }
  const double stated = coarse["step_error"];
  std::printf("4 equal steps: error stated %.4g, against 256 steps %.4g\n", stated, reference);
  EXPECT_TRUE(coarse["step_error_measured"].get<bool>());
  EXPECT_GE(stated, reference);
  EXPECT_LE(stated, 3.0 * reference);
  ASSERT_TRUE(coarse.contains("warnings"));
  EXPECT_NE(coarse["warnings"][0].get<std::string>().find("do not resolve"), std::string::npos);
  EXPECT_FALSE(fine.contains("warnings")) << fine["warnings"];
}

TEST(TransientBounds, TinyDriveIsSolvedNotPrintedAsZeros) {
  // Reference: in the steel's initial linear range the field is proportional to the current, so
  // a 1e-12 A step and a 1e-6 A step give the same lambda / I at the end of the run and the
  // same t63 (tolerance 1e-3 relative: the adaptive steps of the two runs differ only through
  // Newton's round-off). Before, Newton took the 1e-12 A drive for converged at once (its
  // residual floor was in milliamperes) and printed lambda = 0 in every row.
  const nlohmann::json tiny = transient_json("--current 1e-12 --duration 0.1");
  const nlohmann::json small = transient_json("--current 1e-6 --duration 0.1");
  ASSERT_FALSE(tiny.is_null() || small.is_null());
  const double per_ampere_tiny = double(tiny["flux_linkage"].back()) / 1e-12;
  const double per_ampere_small = double(small["flux_linkage"].back()) / 1e-6;
  std::printf("lambda / I at 100 ms: %.6g H (1e-12 A), %.6g H (1e-6 A)\n", per_ampere_tiny,
              per_ampere_small);
  EXPECT_GT(per_ampere_tiny, 0.0);
  EXPECT_NEAR(per_ampere_tiny, per_ampere_small, 1e-3 * per_ampere_small);
  ASSERT_TRUE(tiny["t63"].is_number() && small["t63"].is_number());
  EXPECT_NEAR(double(tiny["t63"]), double(small["t63"]), 1e-3 * double(small["t63"]));
}

TEST(TransientBounds, ResistanceThatMakesTheRunEndlessIsRefusedWithTheLargestAllowed) {
  // --resistance 1e300 gave L/R = 3e-301 s: the adaptive steps fell to their floor (1e-10 of the
  // duration) and the run went on for minutes without a word. Now exit 2 before any step,
  // naming the resistance and the largest one for which L/R >= 1e-9 of the duration.
  const auto run = run_rheomag("transient " + kValve +
                               " --voltage 12 --resistance 1e300 --duration 0.05 --quiet");
  EXPECT_EQ(run.code, 2) << run.err;
  EXPECT_NE(run.err.find("resistance 1e+300 Ohm"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("expected a resistance up to"), std::string::npos) << run.err;
}

TEST(TransientBounds, ProgressGivesTheTimeLeft) {
  // Issue 36: the progress line showed the simulated time only.
  const auto run = run_rheomag("transient " + kValve + " --current 1 --duration 0.02 --steps 20");
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.err.find("of 0.02 s ("), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(" s left"), std::string::npos) << run.err;
}

}  // namespace
