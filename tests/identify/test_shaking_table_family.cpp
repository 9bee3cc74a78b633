// A second lab's damper (tests/data/labcontrol: UTFPR's shaking table, 100 Hz, coil level not
// recorded, each test with its own load-cell zero and most starting at rest): a `damper` family
// fitted on half of the tests at each of four coil levels predicts the other half.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "identify/current_dependent_fit.hpp"
#include "lumped/phenomenological.hpp"
#include "lumped/recording_io.hpp"

using namespace rheomag::identify;
using rheomag::lumped::Recording;

namespace {

std::vector<Recording> read(const std::vector<std::string>& names) {
  std::vector<Recording> recs;
  for (const std::string& name : names)
    recs.push_back(rheomag::lumped::read_recording(std::string(RHEOMAG_TEST_DATA) + "/labcontrol/" +
                                                   name + ".csv"));
  return recs;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// The training half: the odd tests at each of the four levels.
std::vector<Recording> odd_tests() {
  return read({"0V_test1_1", "0V_test3_1", "0V_test5_1", "0V_test7_1", "0V_test9_1",
               "0x87V_test1_2", "0x87V_test3_2", "0x87V_test5_2", "0x87V_test7_2", "0x87V_test9_2",
               "1x98V_test_B_1", "1x98V_test_B_5", "1x98V_test_B_7", "1x98V_test_B_9",
               "3x21V_test_A_1", "3x21V_test_A_3", "3x21V_test_A_5", "3x21V_test_A_7",
               "3x21V_test_A_9"});
}

/// The predicted half: the even tests at each level (at 1.98 V B.3, 6, 8, 10: no B.2 or B.4).
std::vector<Recording> even_tests() {
  return read({"0V_test2_1", "0V_test4_1", "0V_test6_1", "0V_test8_1", "0V_test10_1",
               "0x87V_test2_2", "0x87V_test4_2", "0x87V_test6_2", "0x87V_test8_2", "0x87V_test10_2",
               "1x98V_test_B_3", "1x98V_test_B_6", "1x98V_test_B_8", "1x98V_test_B_10",
               "3x21V_test_A_2", "3x21V_test_A_4", "3x21V_test_A_6", "3x21V_test_A_8",
               "3x21V_test_A_10"});
}

}  // namespace

// Reference: the recordings themselves (held-out tests, never fitted). Measured 2026-12-04 with
// the default decimation and starts: predicted median 89.6 % (19 tests), lowest FIT but one
// 78.9 % (0 V test 10); the family's tests at 0 V are noise-limited
// (repeatability 92-96 %). Before the tare the median was 86.7 % (training median 85.3 -> 89.0 %).
// Tolerances: median >= 88 %, lowest >= 77 % (2 points under the measurement; the fit's
// multi-start makes it platform-dependent to about a point). 0x87V test 8 and 3x21V A.8 move
// after 0.06 and 0.11 s, shorter than the 0.2 s a rest needs, but hold exactly still until then,
// so they are tared on that (LeadingRest.AShortRestExactlyStillCounts; 2026-12-05): test 8,
// whose zero is 160 N below the others', 44.7 -> 91.7 %, A.8 93.5 -> 93.7 %; the predicted median
// 89.6 -> 90.1 %, lowest 78.9 % (0 V test 10). The level calibrated on
// each tared test's first steady drive cycle has a gain of 0.90-1.21 (tolerance 0.8-1.3; on its
// first moving cycle it was 0.88-1.21); on the first cycle from t = 0, which is the rest, it was
// -0.3 to 1e11. Since the level in motion is fitted
// relative to the rest (2026-12-06): median 90.4 %, lowest 79.7 % (0.87 V test 10).
TEST(ShakingTableFamily, HalfTheTestsAtFourLevelsPredictTheOtherHalf) {
  const std::vector<Recording> training = odd_tests();
  const std::vector<Recording> predicted = even_tests();
  const FamilyFit r = fit_current_dependent(training, "damper", predicted, FamilyFitOptions{});
  ASSERT_EQ(r.predicted.size(), predicted.size());
  std::vector<double> fits;
  for (const FamilyMember& m : r.predicted) {
    fits.push_back(m.metrics.fit_percent);
    const auto is = [&](const char* name) { return m.csv_path.find(name) != std::string::npos; };
    if (is("0x87V_test8_2") || is("3x21V_test_A_8")) {  // 6 and 11 samples exactly still
      EXPECT_NEAR(m.rest_seconds, is("0x87V_test8_2") ? 0.06 : 0.11, 1e-9) << m.csv_path;
    } else {
      EXPECT_GT(m.rest_seconds, 0.3) << m.csv_path;
      ASSERT_TRUE(m.level.has_value()) << m.csv_path;
      EXPECT_GT(m.level->start_seconds, 0.3) << m.csv_path;
    }
    EXPECT_GE(m.metrics.fit_percent, 77.0) << m.csv_path;
    ASSERT_TRUE(m.level.has_value()) << m.csv_path;
    EXPECT_GT(m.level->gain, 0.8) << m.csv_path;
    EXPECT_LT(m.level->gain, 1.3) << m.csv_path;
  }
  EXPECT_GE(median(fits), 88.0);
  // This table's inertance is seen (the inertance check, docs/damper-model.md): fitted, it removes
  // 52 % of the residual energy left with it held at 0 (measured 2026-12-05: 96 kg; held at 0
  // the predicted median falls from 89.6 to 83.7 %), so it is kept.
  ASSERT_TRUE(r.fit.inertance_gain.has_value());
  EXPECT_GE(*r.fit.inertance_gain, 0.1);
  for (const FittedParameter& p : r.fit.params) {
    if (p.name == "inertance") {
      EXPECT_FALSE(p.fixed);
    }
  }
}

// Reference: the recordings themselves (held-out tests). A LuGre model has no gas spring, and this
// table's displacement runs from 0 to about 20 mm, so in motion the damper's force sits a gas
// spring's mean (about 4 500 N/m x 10 mm) above its level at rest. The tare used to pin the model's
// level in motion to the rest's: the 0 V tests, where that mean is a large part of the force, were
// predicted at 45.6-51.6 % (median of all 19: 76.4 %; measured 2026-12-06 on the previous build).
// The offset now sets the level in motion relative to the rest (PhenoSettings::rest_reference):
// 0 V 77.6-82.8 %, median 81.4 %, the offset 39 N above the rests' level. Tolerances: a few
// points under the measured values; the previous build fails every one of them.
TEST(ShakingTableFamily, AModelWithoutAGasSpringKeepsItsLevelInMotion) {
  const std::vector<Recording> training = odd_tests();
  const std::vector<Recording> predicted = even_tests();
  const FamilyFit r = fit_current_dependent(training, "lugre", predicted, FamilyFitOptions{});
  ASSERT_EQ(r.predicted.size(), predicted.size());
  std::vector<double> fits;
  for (const FamilyMember& m : r.predicted) {
    fits.push_back(m.metrics.fit_percent);
    if (m.csv_path.find("/0V_") != std::string::npos) {
      EXPECT_GE(m.metrics.fit_percent, 74.0) << m.csv_path;
    }
  }
  EXPECT_GE(median(fits), 79.0);
  const auto k = static_cast<std::size_t>(
      rheomag::lumped::pheno_param_index(rheomag::lumped::PhenoKind::lugre, "offset"));
  const double above_rest = r.fit.params[k].value - r.fit.setup.settings.rest_reference;
  EXPECT_GT(above_rest, 25.0);
  EXPECT_LT(above_rest, 60.0);
}

// A motion drive's single-sample acquisition glitches (lumped/motion_glitches.hpp) are read
// repaired by the grey-box models: five velocity samples of each training test dropped to 0 at
// its fastest strokes (a 0.1 m/s sample lost at 100 Hz is a 10 m/s^2 spike to the inertance).
// Reference: the same family fitted on the tests as published; the inertance within 2 % and each
// training FIT within 0.2 point, the repeatability given where it is given without the glitches.
// Measured 2026-12-07 (motion lead 0): 77.08 against 76.98 kg, the FITs to 0.1 point; before the
// repair 58.7 kg and 0 V test 1 at 85.5 % against 88.7 %.
TEST(ShakingTableFamily, VelocityDropoutsInTheTrainingTestsLeaveTheFamilyAsWithoutThem) {
  const std::vector<Recording> clean =
      read({"0V_test1_1", "0x87V_test1_2", "1x98V_test_B_1", "3x21V_test_A_1"});
  std::vector<Recording> glitched = clean;
  for (Recording& rec : glitched) {
    std::vector<double>& v = rec.columns.at("velocity");
    std::vector<std::size_t> order(v.size());
    for (std::size_t k = 0; k < v.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return std::abs(v[a]) > std::abs(v[b]); });
    std::vector<std::size_t> dropped;
    for (std::size_t k : order) {
      const bool apart = std::all_of(dropped.begin(), dropped.end(),
                                     [&](std::size_t d) { return (k > d ? k - d : d - k) > 50; });
      if (apart) dropped.push_back(k);
      if (dropped.size() == 5) break;
    }
    for (std::size_t k : dropped) v[k] = 0.0;
  }
  const FamilyFit a = fit_current_dependent(clean, "damper", {}, FamilyFitOptions{});
  const FamilyFit b = fit_current_dependent(glitched, "damper", {}, FamilyFitOptions{});
  const auto inertance = [](const FamilyFit& r) {
    for (const FittedParameter& p : r.fit.params)
      if (p.name == "inertance") return p.value;
    return 0.0;
  };
  std::cout << "inertance: " << inertance(a) << " kg as published, " << inertance(b)
            << " kg with the dropouts\n";
  ASSERT_GT(inertance(a), 0.0);
  EXPECT_NEAR(inertance(b) / inertance(a), 1.0, 0.02);
  ASSERT_EQ(a.training.size(), b.training.size());
  for (std::size_t i = 0; i < a.training.size(); ++i) {
    EXPECT_NEAR(b.training[i].metrics.fit_percent, a.training[i].metrics.fit_percent, 0.2)
        << a.training[i].csv_path;
    EXPECT_EQ(b.training[i].repeatability.has_value(), a.training[i].repeatability.has_value())
        << a.training[i].csv_path;
  }
}
