// A field level the family never saw, above its highest: a `damper` family fitted on three coil
// levels of two real dampers predicts the tests at the higher levels (held out, never fitted),
// names them beyond its training drive, and extrapolates its yield along its tangent
// (PhenoSettings::field_high) instead of the quadratic's curvature.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "identify/current_dependent_fit.hpp"
#include "lumped/recording_io.hpp"

using namespace rheomag::identify;
using rheomag::lumped::Recording;

namespace {

std::vector<Recording> read(const std::string& dir, const std::vector<std::string>& names) {
  std::vector<Recording> recs;
  for (const std::string& name : names) {
    const std::string path = dir + name + ".csv";
    if (!std::filesystem::exists(path)) return {};
    recs.push_back(rheomag::lumped::read_recording(path));
  }
  return recs;
}

/// Every predicted test lies beyond the family's fitted levels, at `level` against the highest
/// trained `trained_high`, and is named so.
void expect_field_beyond(const FamilyFit& r, double trained_high) {
  EXPECT_EQ(r.fit.setup.settings.field_high, trained_high);
  for (const FamilyMember& m : r.predicted) {
    ASSERT_FALSE(m.beyond.empty()) << m.csv_path;
    EXPECT_EQ(m.beyond.front().quantity, "field") << m.csv_path;
    EXPECT_GT(m.beyond.front().value, trained_high) << m.csv_path;
  }
}

}  // namespace

// The UTFPR shaking table (tests/data/labcontrol): trained on the odd tests at 0, 0.87 and 1.98 V
// (labelled 0, 0.134 and 0.305 A), predicting the even 3.21 V tests (0.495 A). Reference: the
// recordings themselves. Measured 2026-12-05 (default decimation and starts): FIT 85.0, 85.1,
// 85.3, 86.7, 88.3 %; with the quadratic's curvature carried beyond 0.305 A (the model before)
// 77.8-80.8 %, every test over-predicted (calibrated gains 0.84-0.91; now 0.91-0.97): three
// levels fix the quadratic exactly, and this damper's yield grows as b^2 up to 0.305 A but about
// linearly above it. Tolerance: each >= 83 % (2 points under the lowest; the multi-start makes
// the fit platform-dependent to about a point), which the quadratic misses by 2 points or more.
TEST(UnseenFieldLevel, ShakingTableThreeLevelsPredictTheHighest) {
  const std::string dir = std::string(RHEOMAG_TEST_DATA) + "/labcontrol/";
  const std::vector<Recording> training = read(
      dir, {"0V_test1_1", "0V_test3_1", "0V_test5_1", "0V_test7_1", "0V_test9_1", "0x87V_test1_2",
            "0x87V_test3_2", "0x87V_test5_2", "0x87V_test7_2", "0x87V_test9_2", "1x98V_test_B_1",
            "1x98V_test_B_5", "1x98V_test_B_7", "1x98V_test_B_9"});
  const std::vector<Recording> predicted = read(
      dir,
      {"3x21V_test_A_2", "3x21V_test_A_4", "3x21V_test_A_6", "3x21V_test_A_8", "3x21V_test_A_10"});
  ASSERT_EQ(training.size(), 14u);
  ASSERT_EQ(predicted.size(), 5u);
  const FamilyFit r = fit_current_dependent(training, "damper", predicted, FamilyFitOptions{});
  expect_field_beyond(r, 0.3051);
  for (const FamilyMember& m : r.predicted) EXPECT_GE(m.metrics.fit_percent, 83.0) << m.csv_path;
}

// The UTFSM damper (shared/data/utfsm, M. Quiroz 2022): trained on the 25 mm and 10 mm tests at
// 0, 0.25 and 0.5 A, predicting those at 0.75 and 1 A. Reference: the recordings. Measured
// 2026-12-05: FIT 81.3 (25 mm / 0.5 Hz / 1 A) ... 96.2 %, each test 1.9-13.1 points above the
// quadratic's extrapolation (68.2-93.8 %; 1 A at 25 mm / 0.5 Hz 68.2, at 10 mm 71.4). Tolerance:
// each >= 79 %, the 1 A tests each >= 79 % too, which the quadratic missed by 8-11 points.
TEST(UnseenFieldLevel, UtfsmThreeLevelsPredictTheUpperTwo) {
  const std::string dir = std::string(RHEOMAG_SHARED_DIR) + "/data/utfsm/";
  std::vector<std::string> train_names, predict_names;
  for (const char* test : {"25mm0x1Hz", "25mm0x25Hz", "25mm0x5Hz", "10mm1Hz"}) {
    for (const char* current : {"0A", "0x25A", "0x5A"})
      train_names.push_back(test + std::string(current));
    for (const char* current : {"0x75A", "1A"})
      predict_names.push_back(test + std::string(current));
  }
  const std::vector<Recording> training = read(dir, train_names);
  const std::vector<Recording> predicted = read(dir, predict_names);
  if (training.empty() || predicted.empty()) GTEST_SKIP() << "shared utfsm recordings not present";
  const FamilyFit r = fit_current_dependent(training, "damper", predicted, FamilyFitOptions{});
  expect_field_beyond(r, r.fit.setup.settings.field_high);
  EXPECT_NEAR(r.fit.setup.settings.field_high, 0.5, 0.05);  // the measured 0.5 A and its noise
  for (const FamilyMember& m : r.predicted) EXPECT_GE(m.metrics.fit_percent, 79.0) << m.csv_path;
}
