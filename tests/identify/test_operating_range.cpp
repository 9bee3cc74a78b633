// The drive a model was fitted on (identify/operating_range.hpp): its extent on recordings whose
// extremes are known in closed form, what of another recording lies beyond it, and the range as
// the fitted-model JSON carries it (written, read back, refused when malformed).

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "identify/fit_model_json.hpp"
#include "identify/greybox.hpp"
#include "identify/operating_range.hpp"

using namespace rheomag::identify;
using rheomag::lumped::Recording;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A sine stroke of amplitude `a` [m] at `f` [Hz] around `centre`, 100 Hz for 10 s, at a
/// constant current `i` [A] with one spike of 5 A at sample 500.
Recording stroke(double a, double f, double i, double centre = 0.0) {
  Recording rec;
  std::vector<double> x, v, c;
  for (int k = 0; k < 1000; ++k) {
    const double t = 0.01 * k;
    rec.t.push_back(t);
    x.push_back(centre + a * std::sin(2 * kPi * f * t));
    v.push_back(a * 2 * kPi * f * std::cos(2 * kPi * f * t));
    c.push_back(k == 500 ? 5.0 : i);
  }
  rec.columns = {{"displacement", x}, {"velocity", v}, {"current", c}, {"force", v}};
  rec.meta.drive = {"displacement", "velocity", "current"};
  rec.meta.output = "force";
  rec.csv_path = "stroke.csv";
  return rec;
}

const DriveColumns kDamperColumns{"current", "velocity", "displacement"};

}  // namespace

// A 10 mm / 1 Hz stroke about 12 mm at 0.5 A: the field's extent is the level (the one 5 A
// spike, 0.1 % of the samples, is past the 99.5th percentile), the peak speed 2 pi f a and the
// stroke amplitude a, whatever the centre. Tolerance 1e-3 relative: the 100 Hz samples reach
// the sine's extremes to within 1 - cos(2 pi 0.005) ~ 5e-4 and the percentiles drop the top 0.5 %.
TEST(OperatingRange, OneRecordingsExtentIsItsLevelPeakSpeedAndAmplitude) {
  const OperatingRange r = operating_range(stroke(0.01, 1.0, 0.5, 0.012), kDamperColumns);
  ASSERT_TRUE(r.field && r.speed && r.stroke);
  EXPECT_EQ(r.field->low, 0.5);
  EXPECT_EQ(r.field->high, 0.5);
  EXPECT_NEAR(r.speed->high, 2 * kPi * 0.01, 1e-3 * 2 * kPi * 0.01);
  EXPECT_EQ(r.speed->low, r.speed->high);
  EXPECT_NEAR(r.stroke->high, 0.01, 1e-3 * 0.01);
  EXPECT_EQ(r.field->column, "current");
  EXPECT_EQ(r.stroke->column, "displacement");
  // Samples [0, 400) only: the same sine, so the same extent; a column the recording lacks, none.
  const OperatingRange part =
      operating_range(stroke(0.01, 1.0, 0.5), {"voltage", "velocity", ""}, 0, 400);
  EXPECT_FALSE(part.field.has_value());
  EXPECT_FALSE(part.stroke.has_value());
  EXPECT_NEAR(part.speed->high, r.speed->high, 1e-3 * r.speed->high);
}

// A family's range spans its recordings: levels 0 ... 1 A, peak speeds and strokes from the
// smallest recording's to the largest's.
TEST(OperatingRange, AFamilySpansItsRecordings) {
  const OperatingRange a = operating_range(stroke(0.025, 0.1, 0.0), kDamperColumns);
  const OperatingRange b = operating_range(stroke(0.01, 1.0, 1.0), kDamperColumns);
  const OperatingRange r = span(span(OperatingRange{}, a), b);
  EXPECT_EQ(r.field->low, 0.0);
  EXPECT_EQ(r.field->high, 1.0);
  EXPECT_EQ(r.speed->low, a.speed->high);   // 2 pi 0.1 0.025 = 0.0157 m/s
  EXPECT_EQ(r.speed->high, b.speed->high);  // 2 pi 1 0.01 = 0.0628 m/s
  EXPECT_EQ(r.stroke->low, b.stroke->low);
  EXPECT_EQ(r.stroke->high, a.stroke->high);
}

// Beyond the range: a field more than 5 % of the levels' span above or below them, a peak speed
// or stroke more than 1.25 x beyond the largest or smallest trained one; nothing within.
TEST(OperatingRange, BeyondTheTrainedDriveIsNamedAndWithinItIsNot) {
  const OperatingRange trained = span(operating_range(stroke(0.025, 0.1, 0.0), kDamperColumns),
                                      operating_range(stroke(0.01, 1.0, 0.5), kDamperColumns));
  EXPECT_TRUE(
      beyond_range(trained, operating_range(stroke(0.02, 0.3, 0.25), kDamperColumns)).empty());
  EXPECT_TRUE(beyond_range(trained, operating_range(stroke(0.02, 0.3, 0.52), kDamperColumns))
                  .empty());  // 0.02 A above, within the 0.025 A margin
  const std::vector<RangeExcess> high =
      beyond_range(trained, operating_range(stroke(0.02, 0.3, 0.75), kDamperColumns));
  ASSERT_EQ(high.size(), 1u);
  EXPECT_EQ(high[0].quantity, "field");
  EXPECT_EQ(high[0].value, 0.75);
  EXPECT_EQ(high[0].low, 0.0);
  EXPECT_EQ(high[0].high, 0.5);
  EXPECT_EQ(high[0].text(),
            "field: current up to 0.75 A, above the trained 0 ... 0.5 A (the model's field "
            "dependence is extrapolated)");
  // A 2 mm / 5 Hz stroke: its peak speed (0.063 m/s) was trained, its amplitude was not.
  const std::vector<RangeExcess> small =
      beyond_range(trained, operating_range(stroke(0.002, 5.0, 0.25), kDamperColumns));
  ASSERT_EQ(small.size(), 1u);
  EXPECT_EQ(small[0].quantity, "stroke");
  EXPECT_NEAR(small[0].value, 0.002, 1e-5);
  EXPECT_EQ(small[0].text().rfind("stroke: displacement amplitude 0.002 m, below the trained "
                                  "amplitudes 0.01 ... 0.025 m",
                                  0),
            0u)
      << small[0].text();
  // A fit at one level of 0 A: a recording at 0 A with 5 mA of offset is not beyond it (the
  // 0.01 A floor of the margin), one at 0.25 A is.
  const OperatingRange zero = operating_range(stroke(0.01, 1.0, 0.0), kDamperColumns);
  EXPECT_TRUE(
      beyond_range(zero, operating_range(stroke(0.01, 1.0, 0.005), kDamperColumns)).empty());
  EXPECT_EQ(beyond_range(zero, operating_range(stroke(0.01, 1.0, 0.25), kDamperColumns)).size(),
            1u);
}

// The fitted-model JSON carries the range ("operating_range") and the reader gives it back
// exactly; a document without it reads as before (no range, no check); a malformed one is
// refused naming the key.
TEST(OperatingRange, FittedModelJsonCarriesItAndTheReaderChecksIt) {
  const Recording rec = stroke(0.01, 1.0, 0.5);
  GreyboxFit fit;
  fit.model = "bingham";
  fit.setup = rheomag::lumped::greybox_setup_for(rec, rheomag::lumped::PhenoKind::bingham);
  for (const auto& p : rheomag::lumped::pheno_params(rheomag::lumped::PhenoKind::bingham)) {
    FittedParameter q;
    q.name = p.name;
    q.value = 0.1;
    fit.params.push_back(q);
  }
  nlohmann::json j = fit_model_json(fit, rec.meta);
  const FitModel without = parse_fit_model_json(j.dump(), "model.json");
  EXPECT_FALSE(without.operating_range.has_value());
  EXPECT_TRUE(beyond_fitted_range(without, stroke(0.01, 1.0, 3.0)).empty());
  const OperatingRange range = operating_range(rec, drive_columns(fit));
  j["operating_range"] = operating_range_json(range);
  const FitModel with = parse_fit_model_json(j.dump(), "model.json");
  ASSERT_TRUE(with.operating_range.has_value());
  EXPECT_EQ(with.operating_range->field->high, range.field->high);
  EXPECT_EQ(with.operating_range->speed->high, range.speed->high);
  EXPECT_EQ(with.operating_range->stroke->low, range.stroke->low);
  const std::vector<RangeExcess> beyond = beyond_fitted_range(with, stroke(0.01, 1.0, 3.0));
  ASSERT_EQ(beyond.size(), 1u);
  EXPECT_EQ(beyond[0].quantity, "field");
  j["operating_range"]["field"]["high"] = -1.0;
  try {
    parse_fit_model_json(j.dump(), "model.json");
    FAIL() << "a range with high < low was read";
  } catch (const rheomag::InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "model.json: key 'operating_range.field.high': expected a value at least 'low' "
              "(0.500000)");
  }
  j["operating_range"] = 3;
  EXPECT_THROW(parse_fit_model_json(j.dump(), "model.json"), rheomag::InputError);
}
