// Current-dependent grey-box fits across a family of recordings (paper 001's protocol): a LuGre
// model with field-scaled terms linear in the current is recovered from its own simulated, noisy
// recordings at two frequencies and predicts a third; and the real utfsm damper recordings are
// fitted at 0.1 + 0.25 Hz and predict 0.5 Hz with the accuracy measured when this was written.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "identify/current_dependent_fit.hpp"
#include "identify/family_cross_validation.hpp"
#include "identify/family_fit_output.hpp"
#include "identify/family_report.hpp"
#include "lumped/recording_io.hpp"

using namespace rheomag::lumped;
using namespace rheomag::identify;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kAmplitude = 0.025;  ///< [m] stroke amplitude, as the utfsm tests
constexpr int kDecimation = 2;

/// Sinusoidal damper recording (2 cycles, 200 samples per cycle) at frequency f and current i;
/// force column left at zero.
Recording sine_recording(double f, double current) {
  Recording rec;
  const double dt = 1.0 / (200.0 * f);
  std::vector<double> x, v;
  for (int k = 0; k < 400; ++k) {
    const double t = k * dt;
    rec.t.push_back(t);
    x.push_back(kAmplitude * std::sin(2 * kPi * f * t));
    v.push_back(kAmplitude * 2 * kPi * f * std::cos(2 * kPi * f * t));
  }
  rec.columns["displacement"] = x;
  rec.columns["velocity"] = v;
  rec.columns["current"] = std::vector<double>(x.size(), current);
  rec.columns["force"] = std::vector<double>(x.size(), 0.0);
  rec.meta.drive = {"displacement", "velocity", "current"};
  rec.meta.output = "force";
  rec.meta.rig.kind = rheomag::lumped::RigKind::damper;
  rec.csv_path = "sine_" + std::to_string(f) + "Hz_" + std::to_string(current) + "A.csv";
  return rec;
}

/// rms of the velocity column of the joined training recordings: the fit's eps and motion scale
/// are set from it (GreyboxOptions::eps_fraction), so the simulation must use the same.
double joined_velocity_rms(const std::vector<Recording>& recs) {
  const Recording joined = join_recordings(recs, kDecimation);
  const auto& v = joined.column("velocity");
  double s = 0.0;
  for (double x : v) s += x * x;
  return std::sqrt(s / static_cast<double>(v.size()));
}

/// Fills rec's force with LuGre's output plus Gaussian noise of `noise` x its rms.
void simulate_force(Recording& rec, const std::vector<double>& params, double v_rms, double noise,
                    unsigned seed) {
  GreyboxSetup setup = greybox_setup_for(rec, PhenoKind::lugre);
  setup.settings.eps = GreyboxOptions{}.eps_fraction * v_rms;
  setup.settings.motion_scale = v_rms;
  std::vector<double> y = simulate_pheno(rec, setup, params);
  double rms = 0.0;
  for (double f : y) rms += f * f;
  rms = std::sqrt(rms / static_cast<double>(y.size()));
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, noise * rms);
  for (double& f : y) f += n(rng);
  rec.columns["force"] = y;
}

}  // namespace

// LuGre (paper 001 eqs. 8-9 as in lumped/phenomenological.hpp) with stiffness and viscous force
// linear in the current, simulated at 0.1 and 0.25 Hz for 0, 0.5 and 1 A with 1 % noise, fitted
// jointly: the current-scaled parameters (stiffness, stiffness_per_field, viscous,
// viscous_per_field) and the shape (rate, exponent) within 5 % (noise-limited; the standard
// errors are below 1 %). Predicting 0.5 Hz (never fitted) at 0.25 and 0.75 A (never fitted
// either): RE (paper 001 eq. 10) below 0.02, i.e. the noise level (1 % rms noise gives RE ~0.01).
TEST(CurrentDependent, LuGreRecoversParametersAndPredictsAThirdFrequency) {
  const std::vector<double> truth = {40.0, 260.0, 2.0, 1000.0,
                                     90.0, 700.0, 0.4, 0.0};  // order of pheno_params(lugre)
  std::vector<Recording> training;
  for (double f : {0.1, 0.25})
    for (double i : {0.0, 0.5, 1.0}) training.push_back(sine_recording(f, i));
  const double v_rms = joined_velocity_rms(training);
  unsigned seed = 1;
  for (Recording& r : training) simulate_force(r, truth, v_rms, 0.01, seed++);
  std::vector<Recording> prediction;
  for (double i : {0.25, 0.75}) {
    prediction.push_back(sine_recording(0.5, i));
    simulate_force(prediction.back(), truth, v_rms, 0.01, seed++);
  }
  FamilyFitOptions options;
  options.decimation = kDecimation;
  const FamilyFit r = fit_current_dependent(training, "lugre", prediction, options);
  for (const char* name :
       {"stiffness", "stiffness_per_field", "rate", "viscous", "viscous_per_field", "exponent"}) {
    const int k = pheno_param_index(PhenoKind::lugre, name);
    ASSERT_GE(k, 0) << name;
    EXPECT_NEAR(r.fit.params[k].value, truth[k], 0.05 * std::abs(truth[k])) << name;
  }
  ASSERT_EQ(r.predicted.size(), 2u);
  for (const FamilyMember& m : r.predicted) EXPECT_LT(m.metrics.re, 0.02) << m.csv_path;
  for (const FamilyMember& m : r.training) EXPECT_LT(m.metrics.re, 0.02) << m.csv_path;
}

// Leave-one-recording-out cross-validation. LuGre recordings as above, noise-free, with the
// 0.25 Hz / 0.5 A one's force scaled by 1.1 (a test whose level is off, as real tests scatter).
// Reference: fitted on the other five (exact) recordings the model is the truth, so its
// prediction of the scaled test is the unscaled force s: error 0.1 s against a spread 1.1 s,
// FIT = 100 (1 - 0.1 / 1.1) = 90.91 % (tolerance 0.1 point: the fit's eps and motion scale come
// from the five recordings' velocity rms, and the output is zero-mean over whole cycles only
// after the start from rest). Fitted on all six, the scaled test pulls the fit its way, so its
// own FIT is higher than held out (least squares). With one level fitted on its first samples
// (two cycles: no drive period from two upward crossings, so the first fifth), the held-out
// prediction is the scaled test again: FIT above 99.8 % and gain 1.1 (0.5 %), against a pure FIT
// of 90.91 % (0.2 point) on the same samples.
// Each held-out row is exactly the prediction of a family fitted without that recording and
// started from the fit of the half that does not hold it (one start, refit_iterations: 1e-9), or
// from nominal for cold refits (same starts and seed: 1e-9), whatever the number of threads the
// refits share (1 or 3: identical).
TEST(CurrentDependent, CrossValidationPredictsEachRecordingFromTheOthers) {
  const std::vector<double> truth = {40.0, 260.0, 2.0, 1000.0, 90.0, 700.0, 0.4, 0.0};
  std::vector<Recording> training;
  for (double f : {0.1, 0.25})
    for (double i : {0.0, 0.5, 1.0}) training.push_back(sine_recording(f, i));
  const double v_rms = joined_velocity_rms(training);
  for (Recording& r : training) simulate_force(r, truth, v_rms, 0.0, 1);
  const std::size_t scaled = 4;  // 0.25 Hz, 0.5 A
  for (double& f : training[scaled].columns["force"]) f *= 1.1;
  FamilyFitOptions options;
  options.decimation = kDecimation;
  options.cross_validate = true;
  options.greybox.threads = 1;
  const FamilyFit r = fit_current_dependent(training, "lugre", {}, options);
  ASSERT_EQ(r.held_out.size(), training.size());
  for (std::size_t k = 0; k < training.size(); ++k)
    EXPECT_EQ(r.held_out[k].csv_path, training[k].csv_path);
  const FamilyMember& held = r.held_out[scaled];
  EXPECT_NEAR(held.metrics.fit_percent, 100.0 * (1.0 - 0.1 / 1.1), 0.1);
  EXPECT_GT(r.training[scaled].metrics.fit_percent, held.metrics.fit_percent + 1.0);
  ASSERT_TRUE(held.band.has_value());
  ASSERT_TRUE(held.level.has_value());
  EXPECT_EQ(held.level->samples, training[scaled].t.size() / 5);
  EXPECT_GT(held.level->fit_percent, 99.8);
  EXPECT_NEAR(held.level->gain, 1.1, 0.0055);
  EXPECT_NEAR(held.level->pure_fit_percent, 100.0 * (1.0 - 0.1 / 1.1), 0.2);
  EXPECT_FALSE(r.training[scaled].level.has_value());  // training rows are fitted, not predicted
  for (const FamilyMember& m : r.held_out)  // both frequencies and two tests at every level
    EXPECT_TRUE(m.beyond.empty()) << m.csv_path;

  // The halves: every field level (0, 0.5, 1 A) in each, and both frequencies (two tests a
  // level: the first half 0.1 Hz at 0 and 1 A, 0.25 Hz at 0.5 A), in training order.
  const std::vector<std::vector<Recording>> halves = cross_validation_halves(training, "lugre");
  ASSERT_EQ(halves.size(), 2u);
  ASSERT_EQ(halves[0].size(), 3u);
  ASSERT_EQ(halves[1].size(), 3u);
  EXPECT_EQ(halves[0][0].csv_path, training[0].csv_path);  // 0.1 Hz, 0 A
  EXPECT_EQ(halves[0][1].csv_path, training[2].csv_path);  // 0.1 Hz, 1 A
  EXPECT_EQ(halves[0][2].csv_path, training[4].csv_path);  // 0.25 Hz, 0.5 A
  EXPECT_EQ(halves[1][0].csv_path, training[1].csv_path);  // 0.1 Hz, 0.5 A
  EXPECT_EQ(halves[1][1].csv_path, training[3].csv_path);  // 0.25 Hz, 0 A
  EXPECT_EQ(halves[1][2].csv_path, training[5].csv_path);  // 0.25 Hz, 1 A
  const auto in_half = [&](const std::vector<Recording>& half) {
    return std::any_of(half.begin(), half.end(),
                       [&](const Recording& h) { return h.csv_path == training[scaled].csv_path; });
  };
  const std::vector<Recording>& other = in_half(halves[0]) ? halves[1] : halves[0];
  ASSERT_FALSE(in_half(other));
  GreyboxOptions direct = options.greybox;
  for (const FittedParameter& p : fit_greybox_family(other, "lugre", direct, kDecimation).params)
    direct.start.push_back(p.value);
  direct.starts = 1;
  direct.max_iterations = options.refit_iterations;
  std::vector<Recording> others = training;
  others.erase(others.begin() + static_cast<std::ptrdiff_t>(scaled));
  const GreyboxFit without = fit_greybox_family(others, "lugre", direct, kDecimation);
  EXPECT_NEAR(held.metrics.fit_percent,
              evaluate_family_member(training[scaled], without).metrics.fit_percent, 1e-9);

  // Cold refits (refit_iterations 0): each from nominal with the main fit's starts, as an
  // explicit fit without the recording.
  options.refit_iterations = 0;
  const FamilyFit cold = fit_current_dependent(training, "lugre", {}, options);
  const GreyboxFit cold_without = fit_greybox_family(others, "lugre", options.greybox, kDecimation);
  EXPECT_NEAR(cold.held_out[scaled].metrics.fit_percent,
              evaluate_family_member(training[scaled], cold_without).metrics.fit_percent, 1e-9);
  options.refit_iterations = FamilyFitOptions{}.refit_iterations;

  options.greybox.threads = 3;
  const FamilyFit shared = fit_current_dependent(training, "lugre", {}, options);
  for (std::size_t k = 0; k < training.size(); ++k)
    EXPECT_EQ(shared.held_out[k].metrics.fit_percent, r.held_out[k].metrics.fit_percent) << k;

  EXPECT_THROW(fit_current_dependent({training[0], training[1]}, "lugre", {}, options),
               rheomag::InputError);  // leaving one of two out leaves no family
}

// A held-out test outside the drive of the recordings its refit was fitted on is an
// extrapolation, and the held-out rows say so (beyond_range against the other recordings' drive).
// LuGre recordings as above, noise-free: 0.25 Hz at 0, 0.5 and 1 A and 0.1 Hz at 0.5 A. Without
// the 0 A test the others span 0.5 ... 1 A (field below, exactly 0 against 0.5 ... 1); without
// the 1 A test, 0 ... 0.5 A (field above); without the 0.1 Hz test, only the 0.25 Hz peak speed
// (below it by the frequency ratio 0.4, beyond the 1.25 factor); the 0.25 Hz / 0.5 A test lies
// inside the others' drive. The text report names each excess and gives the held-out FIT of the
// one test inside apart; the HTML report's table marks the other three rows.
TEST(CurrentDependent, CrossValidationNamesTheHeldOutTestsItExtrapolates) {
  const std::vector<double> truth = {40.0, 260.0, 2.0, 1000.0, 90.0, 700.0, 0.4, 0.0};
  std::vector<Recording> training = {sine_recording(0.25, 0.0), sine_recording(0.1, 0.5),
                                     sine_recording(0.25, 0.5), sine_recording(0.25, 1.0)};
  const double v_rms = joined_velocity_rms(training);
  for (Recording& r : training) simulate_force(r, truth, v_rms, 0.0, 1);
  FamilyFitOptions options;
  options.decimation = kDecimation;
  options.cross_validate = true;
  const FamilyFit r = fit_current_dependent(training, "lugre", {}, options);
  ASSERT_EQ(r.held_out.size(), 4u);
  const auto excess = [&](std::size_t k) {
    EXPECT_EQ(r.held_out[k].beyond.size(), 1u) << k;
    return r.held_out[k].beyond.empty() ? RangeExcess{} : r.held_out[k].beyond.front();
  };
  const RangeExcess below = excess(0), slow = excess(1), above = excess(3);
  EXPECT_EQ(below.quantity, "field");
  EXPECT_EQ(below.value, 0.0);
  EXPECT_EQ(below.low, 0.5);
  EXPECT_EQ(below.high, 1.0);
  EXPECT_EQ(above.quantity, "field");
  EXPECT_EQ(above.value, 1.0);
  EXPECT_EQ(above.low, 0.0);
  EXPECT_EQ(above.high, 0.5);
  EXPECT_EQ(slow.quantity, "speed");
  EXPECT_NEAR(slow.value / slow.high, 0.4, 1e-3);  // the same stroke at 0.1 against 0.25 Hz
  EXPECT_NEAR(slow.high, kAmplitude * 2 * kPi * 0.25, 1e-3 * slow.high);
  EXPECT_TRUE(r.held_out[2].beyond.empty());

  std::ostringstream text;
  write_family_fit_text(r, training.size(), kDecimation, text);
  for (std::size_t k : {0, 1, 3})
    EXPECT_NE(text.str().find("beyond the drive of the recordings its refit was fitted on: " +
                              training[k].csv_path + ": " + r.held_out[k].beyond.front().text()),
              std::string::npos)
        << k << "\n"
        << text.str();
  char within[160];
  std::snprintf(within, sizeof within,
                "held-out FIT within the drive each refit was fitted on: median %.1f %%, lowest "
                "%.1f %% (1 of 4 tests; the other 3 extrapolate, above)",
                r.held_out[2].metrics.fit_percent, r.held_out[2].metrics.fit_percent);
  EXPECT_NE(text.str().find(within), std::string::npos) << text.str();

  // The report's table marks the three held-out rows, each with its excess.
  const std::string html = family_report_html(r, training, {});
  EXPECT_NE(html.find("<td>held out (extrapolated: field: current down to 0 A, below the trained "
                      "0.5 ... 1 A"),
            std::string::npos);
  std::size_t marked = 0;
  for (std::size_t at = html.find("held out (extrapolated: "); at != std::string::npos;
       at = html.find("held out (extrapolated: ", at + 1))
    ++marked;
  EXPECT_EQ(marked, 3u);
}

// Issue 36: a recording given twice counted as two tests (between-recording standard errors
// 23 -> 13.2). The same file under another name (./a.csv, a link) and the same samples under
// another file are refused before any fit, naming both.
TEST(CurrentDependent, DuplicateTrainingRecordingIsRefusedByName) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "rheomag_test_family_duplicate";
  fs::create_directories(dir);
  std::ofstream(dir / "a.csv") << "t\n";
  fs::remove(dir / "link.csv");
  fs::create_symlink("a.csv", dir / "link.csv");
  Recording a = sine_recording(0.1, 0.0), b = sine_recording(0.25, 1.0);
  a.csv_path = (dir / "a.csv").string();
  b.csv_path = (dir / "link.csv").string();
  b.t = a.t;  // same file: its data would be the same too; here only the path decides
  const auto refusal = [](const std::vector<Recording>& training) {
    try {
      fit_current_dependent(training, "lugre", {}, FamilyFitOptions{});
    } catch (const rheomag::InputError& e) {
      return std::string(e.what());
    }
    return std::string("(none)");
  };
  EXPECT_NE(refusal({a, b}).find("link.csv: the same file as " + a.csv_path), std::string::npos)
      << refusal({a, b});
  Recording copy = a;
  copy.csv_path = (dir / "copy.csv").string();
  EXPECT_NE(refusal({a, sine_recording(0.25, 1.0), copy})
                .find("copy.csv: the same samples as " + a.csv_path + " (every column equal)"),
            std::string::npos);
  fs::remove_all(dir);
}

// Joining keeps every n-th sample, shifts time so it increases, and rejects mixed recordings.
TEST(CurrentDependent, JoinRecordingsDecimatesAndRejectsMixedFamilies) {
  const std::vector<Recording> recs = {sine_recording(0.1, 0.0), sine_recording(0.25, 1.0)};
  const Recording j = join_recordings(recs, 4);
  ASSERT_EQ(j.t.size(), 200u);  // 2 x 400 samples, every 4th
  for (std::size_t k = 1; k < j.t.size(); ++k) EXPECT_GT(j.t[k], j.t[k - 1]);
  EXPECT_DOUBLE_EQ(j.column("current")[150], 1.0);
  Recording other = sine_recording(0.5, 0.0);
  other.meta.output = "pressure";
  EXPECT_THROW(join_recordings({recs[0], other}, 1), rheomag::InputError);
  EXPECT_THROW(join_recordings(recs, 0), rheomag::InputError);
  EXPECT_THROW(join_recordings({}, 1), rheomag::InputError);
}

namespace {

/// The utfsm recordings at frequency tag `freq` ("0x1", "0x25", "0x5") for 0, 0.25, ..., 1 A;
/// empty if the shared data folder is absent.
std::vector<Recording> utfsm_recordings(const std::string& test) {
  const std::string dir = std::string(RHEOMAG_SHARED_DIR) + "/data/utfsm/";
  std::vector<Recording> recs;
  for (const char* current : {"0A", "0x25A", "0x5A", "0x75A", "1A"}) {
    const std::string path = dir + test + "Hz" + current + ".csv";
    if (!std::filesystem::exists(path)) return {};
    recs.push_back(read_recording(path));
  }
  return recs;
}

}  // namespace

// Real data (utfsm, M. Quiroz 2022): LuGre with stiffness and viscous force linear in current,
// fitted jointly on 0.1 + 0.25 Hz at all five currents (every 8th sample, one start), predicting
// 0.5 Hz. Measured when written: training RE 0.058-0.199, predicted RE 0.103-0.195 (mean 0.157);
// paper 001's LuGre, fitted per current at 0.75 Hz on a valve, predicted 0.5 Hz with mean RE
// 0.096. Tolerances: measured + 0.03 per recording, mean predicted RE below 0.18.
TEST(CurrentDependent, UtfsmLuGrePredictsHalfHertz) {
  std::vector<Recording> training = utfsm_recordings("25mm0x1");
  const std::vector<Recording> at_025 = utfsm_recordings("25mm0x25");
  const std::vector<Recording> prediction = utfsm_recordings("25mm0x5");
  if (training.empty() || at_025.empty() || prediction.empty())
    GTEST_SKIP() << "shared utfsm recordings not present";
  training.insert(training.end(), at_025.begin(), at_025.end());
  FamilyFitOptions options;
  options.decimation = 8;
  options.greybox.starts = 1;
  const FamilyFit r = fit_current_dependent(training, "lugre", prediction, options);
  ASSERT_EQ(r.predicted.size(), 5u);
  for (const FamilyMember& m : r.training) EXPECT_LT(m.metrics.re, 0.23) << m.csv_path;
  double mean = 0.0;
  for (const FamilyMember& m : r.predicted) {
    EXPECT_LT(m.metrics.re, 0.23) << m.csv_path;
    mean += m.metrics.re / 5.0;
  }
  EXPECT_LT(mean, 0.18);
  // The field-scaled terms grow with current (MR effect), as paper 001's Fig. 9 trends.
  EXPECT_GT(r.fit.params[pheno_param_index(PhenoKind::lugre, "stiffness_per_field")].value, 0.0);
  EXPECT_GT(r.fit.params[pheno_param_index(PhenoKind::lugre, "viscous_per_field")].value, 0.0);
}

// Real data (utfsm): the damper model fitted on the 15 tests at 25 mm (every 8th sample, one
// start) predicts the five 10 mm / 1 Hz tests. The recordings were smoothed by a moving average
// over a tenth of the period (the source's processing: window round(1 / (10 Ts f)) samples, i.e.
// 0.1016 of the measured 0.984 s and 9.835 s periods); the fitted output_smoothing must agree
// within 15 % without being told (measured 0.0921). The field saturates within the tested
// currents: field_saturation k^2 between 0.25 and 4 A^-2 (saturation current 1 / k of 0.5-2 A).
// Predicted FIT measured with field_saturation: 90.2, 90.9, 89.0, 91.3, 96.2 % at 0-1 A (lowest
// 89.0, mean 91.5); tolerance 1.5 points below each of lowest and mean. Without field_saturation
// (field linear in the current) 90.1, 91.9, 86.3, 89.1, 94.6 % (lowest 86.3, mean 90.4): the lowest
// bound fails it; before output_smoothing 84.2-88.1 % (mean 86.4, every 4th sample, two starts).
TEST(CurrentDependent, UtfsmDamperFindsTheRecordingsSmoothingAndPredictsTenMillimetres) {
  std::vector<Recording> training;
  for (const char* test : {"25mm0x1", "25mm0x25", "25mm0x5"}) {
    const std::vector<Recording> recs = utfsm_recordings(test);
    training.insert(training.end(), recs.begin(), recs.end());
  }
  const std::vector<Recording> prediction = utfsm_recordings("10mm1");
  if (training.size() != 15 || prediction.empty())
    GTEST_SKIP() << "shared utfsm recordings not present";
  FamilyFitOptions options;
  options.decimation = 8;
  options.greybox.starts = 1;
  const FamilyFit r = fit_current_dependent(training, "damper", prediction, options);
  ASSERT_EQ(r.predicted.size(), 5u);
  const auto& smoothing = r.fit.params[static_cast<std::size_t>(
      pheno_param_index(PhenoKind::damper, "output_smoothing"))];
  EXPECT_NEAR(smoothing.value, 0.1016, 0.15 * 0.1016);
  const auto& saturation = r.fit.params[static_cast<std::size_t>(
      pheno_param_index(PhenoKind::damper, "field_saturation"))];
  std::printf("field_saturation %.3f A^-2\n", saturation.value);
  EXPECT_GT(saturation.value, 0.25);
  EXPECT_LT(saturation.value, 4.0);
  double lowest = 100.0, mean = 0.0;
  for (const FamilyMember& m : r.predicted) {
    std::printf("%s: predicted FIT %.1f %%\n", m.csv_path.c_str(), m.metrics.fit_percent);
    lowest = std::min(lowest, m.metrics.fit_percent);
    mean += m.metrics.fit_percent / 5.0;
  }
  EXPECT_GE(lowest, 87.5);
  EXPECT_GE(mean, 90.0);
}
