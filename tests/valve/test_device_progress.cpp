// Damper, brake and valve lists report their progress (issue #36: `damper` with 3,000
// velocities ran for minutes without a word): one report per current before its field solve and
// one per evaluated point, done counting up to currents x points, with the same total throughout.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "core/progress.hpp"
#include "valve/brake_report.hpp"
#include "valve/damper_report.hpp"

using namespace rheomag;

namespace {

/// Every event of one evaluation.
struct Heard {
  std::vector<ProgressEvent> events;
  ProgressCallback callback() {
    return [this](const ProgressEvent& e) { events.push_back(e); };
  }
};

/// Checks `heard` for `currents` x `points`: done never decreases and ends at the total, the
/// total is constant, each current is named in a stage.
void expect_counted(const Heard& heard, const std::vector<double>& currents, std::size_t points,
                    const std::string& device) {
  const double total = static_cast<double>(currents.size() * points);
  ASSERT_EQ(heard.events.size(), currents.size() * (points + 1));
  double done = 0.0;
  for (const ProgressEvent& e : heard.events) {
    EXPECT_EQ(e.total, total);
    EXPECT_GE(e.done, done);
    EXPECT_GE(e.elapsed, 0.0);
    done = e.done;
  }
  EXPECT_EQ(done, total);
  EXPECT_EQ(heard.events.front().stage, device + " at 0 A");
  EXPECT_EQ(heard.events.back().stage, device + " at 0.5 A");
}

}  // namespace

TEST(DeviceProgress, DamperReportsEveryPoint) {
  const auto c = cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/damper_piston.toml");
  Heard heard;
  const std::vector<double> currents{0.0, 0.5}, velocities{0.05, 0.1, 0.2};
  const auto report = valve::evaluate_damper(c, currents, velocities, heard.callback());
  EXPECT_EQ(report.points.size(), 6u);
  expect_counted(heard, currents, velocities.size(), "damper");
}

TEST(DeviceProgress, BrakeReportsEveryPoint) {
  const auto c = cases::load_case(std::string(RHEOMAG_SOURCE_DIR) + "/cases/brake_disc.toml");
  Heard heard;
  const std::vector<double> currents{0.0, 0.5}, speeds{10.0, 20.0};
  const auto report = valve::evaluate_brake(c, currents, speeds, heard.callback());
  EXPECT_EQ(report.points.size(), 4u);
  expect_counted(heard, currents, speeds.size(), "brake");
}
