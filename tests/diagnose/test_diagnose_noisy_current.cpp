// Magnetic hysteresis under a noisy measured current (issue 33 point 4). The Duhem candidate is
// driven by the current's noise-robust path (diagnose/current_path.hpp): white noise on the raw
// samples reverses a Duhem state at every sample and erases its memory while the current rests.
// Reference: recordings simulated from a known truth (the bypass rig of the fixture) whose coil
// current is then measured with white noise of 0.1, 0.3 and 0.5 % of its range (1 A).
// Acceptance: hysteresis named in >= 90 % of the recordings with it, and no magnetic_hysteresis
// named on the same noisy currents without it.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "diagnose/candidates/magnetic_hysteresis.hpp"
#include "diagnose/current_path.hpp"
#include "diagnose/diagnose_run.hpp"
#include "lumped/recording_io.hpp"
#include "test_diagnose_fixture.hpp"

namespace {

using rheomag::diagnose::current_path;
using rheomag::diagnose::reversal_band;

/// Number of direction changes of `x` (zero moves skipped).
int reversals(const std::vector<double>& x) {
  int count = 0;
  double last = 0.0;
  for (std::size_t k = 1; k < x.size(); ++k) {
    const double move = x[k] - x[k - 1];
    if (move == 0.0) continue;
    if (last != 0.0 && (move > 0.0) != (last > 0.0)) ++count;
    last = move;
  }
  return count;
}

/// Current steps 0 / 0.5 / 1 / 0.5 A, 75 samples each.
std::vector<double> steps(std::size_t n) {
  const double levels[] = {0.0, 0.5, 1.0, 0.5};
  std::vector<double> i(n);
  for (std::size_t k = 0; k < n; ++k) i[k] = levels[(k / 75) % 4];
  return i;
}

// A clean signal (band 0) is returned unchanged, to the bit.
TEST(CurrentPath, CleanCurrentIsUnchanged) {
  std::vector<double> i(600);
  for (std::size_t k = 0; k < i.size(); ++k) i[k] = 0.5 + 0.5 * std::sin(0.03 * k);
  EXPECT_EQ(current_path(i, 0.0), i);
}

// Steps with 0.5 % noise: the path reverses exactly where the truth does (once per descending
// step pair: 1 -> 0.5 -> 0 and back up, i.e. at each top and bottom), every step stays a step
// (the path crosses half way between two levels within one sample of the truth), and its error
// on the holds is below the noise (rms under 0.5 sigma: a plateau is a mean of ~75 samples).
TEST(CurrentPath, NoisyStepsKeepTheirReversalsAndEdges) {
  const std::size_t n = 1200;
  const auto truth = steps(n);
  const double sigma = 0.005;
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, sigma);
  auto measured = truth;
  for (double& v : measured) v += noise(rng);
  const auto path = current_path(measured, reversal_band(sigma, n));
  EXPECT_GT(reversals(measured), 500);
  EXPECT_EQ(reversals(path), reversals(truth));
  double sse = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    if (k % 75 != 0 && k % 75 != 74) sse += (path[k] - truth[k]) * (path[k] - truth[k]);
  EXPECT_LT(std::sqrt(sse / static_cast<double>(n)), 0.5 * sigma);
  for (std::size_t k = 1; k < n; ++k)
    if (truth[k] != truth[k - 1]) {
      const double mid = 0.5 * (truth[k] + truth[k - 1]);
      EXPECT_EQ(path[k] > mid, truth[k] > mid) << "edge at sample " << k;
      EXPECT_EQ(path[k - 1] > mid, truth[k - 1] > mid) << "edge at sample " << k;
    }
}

/// One recording of the proof and the Duhem field concealed in it (when `hysteresis`).
struct NoisyCurrentRecording {
  rheomag::test::VirtualRecording v;
  double a = 0.0, d = 0.0;
};

/// One recording of the proof: truth simulated on the clean current, then the current measured
/// with white noise of `fraction` of its range.
NoisyCurrentRecording noisy_current_recording(bool hysteresis, double fraction, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto truth = rheomag::test::bypass_rig();
  // Drawn as the confusion proof draws a Duhem field: a log-uniform in 2-10 /A, d in 0.1-0.6.
  const double a = 2.0 * std::pow(5.0, unit(rng)), d = 0.1 + 0.5 * unit(rng);
  const double f = 0.7 + 0.8 * unit(rng);
  if (hysteresis) truth.magnetic_hysteresis = rheomag::diagnose::duhem_field(a, d);
  const auto in =
      rheomag::test::drive(2.4, 300.0,
                           {"displacement=sine:amplitude=0.025,frequency=" + std::to_string(f),
                            "current=steps:levels=0/0.5/1/0.5,period=0.25"});
  NoisyCurrentRecording out{rheomag::test::make_recording(truth, in, 3e4, seed), a, d};
  std::normal_distribution<double> noise(0.0, fraction * 1.0);
  for (double& i : out.v.noisy.columns.at("current")) i += noise(rng);
  return out;
}

double param(const rheomag::diagnose::Finding& f, const std::string& name) {
  for (std::size_t j = 0; j < f.param_names.size(); ++j)
    if (f.param_names[j] == name) return f.params[j];
  ADD_FAILURE() << "no parameter " << name << " in " << f.effect->name();
  return 0.0;
}

/// The finding of `effect` in `d` (nullptr if not named).
const rheomag::diagnose::Finding* named(const rheomag::diagnose::Diagnosis& d,
                                        const std::string& effect) {
  for (const auto& f : d.findings)
    if (f.effect->name() == effect) return &f;
  return nullptr;
}

// The proof: 3 noise levels x 3 seeds, each with and without a concealed Duhem field. A named
// field's loop half width (1 - d)/a is within 20 % of the truth (the tolerance of
// DiagnoseHysteresis; on these drives a and d trade along the half width: seed 13 is fitted
// a = 4.0-4.2 /A, d = 0.62-0.65 against 5.3 /A, 0.53 at every noise level, half width within 1 %).
// RHEOMAG_NOISY_CURRENT_DIR=DIR also writes the recordings there (CSV + sidecar), so that another
// build can diagnose the very same recordings (docs/diagnosis.md, "Noisy drives").
TEST(DiagnoseNoisyCurrent, HysteresisNamedAndNotInventedUnderCurrentNoise) {
  const char* dir = std::getenv("RHEOMAG_NOISY_CURRENT_DIR");
  int with = 0, hits = 0, without = 0, false_findings = 0;
  for (double fraction : {0.001, 0.003, 0.005})
    for (unsigned seed : {11u, 12u, 13u})
      for (bool hysteresis : {true, false}) {
        const auto r = noisy_current_recording(hysteresis, fraction, seed);
        const auto& v = r.v;
        if (dir) {
          std::filesystem::create_directories(dir);
          const std::string name = std::string(dir) + "/" + (hysteresis ? "duhem" : "clean") + "_" +
                                   std::to_string(static_cast<int>(fraction * 1e4)) + "e-4_" +
                                   std::to_string(seed) + ".csv";
          rheomag::lumped::write_recording(v.noisy, name);
        }
        const auto d = rheomag::test::run_diagnosis(v.noisy);
        std::cout << (hysteresis ? "duhem" : "clean") << " noise " << 100 * fraction << " % seed "
                  << seed << " (truth a " << r.a << " d " << r.d << "): final FIT "
                  << d.final_fit_percent << ", noise ceiling " << v.noise_ceiling << "\n";
        rheomag::test::print_findings(d);
        const auto* f = named(d, "magnetic_hysteresis");
        if (hysteresis) {
          ++with;
          if (!f) continue;
          ++hits;
          const double width = (1.0 - param(*f, "d")) / param(*f, "a");
          EXPECT_NEAR(width / ((1.0 - r.d) / r.a), 1.0, 0.2)
              << "seed " << seed << " noise " << fraction;
        } else {
          ++without;
          false_findings += f != nullptr;
        }
      }
  std::cout << "hysteresis named " << hits << "/" << with << ", false " << false_findings << "/"
            << without << "\n";
  EXPECT_GE(hits, static_cast<int>(std::ceil(0.9 * with)));
  EXPECT_EQ(false_findings, 0);
}

// A real recording (UTFSM damper, 25 mm at 0.5 Hz and 1 A, docs/diagnosis.md "Real recordings")
// whose current column is the set-point, measured here with white noise of 0.5 % of it: no loop
// may be invented from the noise (a constant current's path is its mean). Reference: the
// recording itself; the same diagnosis without the noise names no magnetic_hysteresis either.
TEST(DiagnoseNoisyCurrent, NoHysteresisInventedOnARealDamperWithANoisyCurrent) {
  const std::string csv = std::string(RHEOMAG_SHARED_DIR) + "/data/utfsm/25mm0x5Hz1A.csv";
  if (!std::filesystem::exists(csv)) GTEST_SKIP() << csv << " not present";
  auto rec = rheomag::lumped::read_csv_samples(csv);
  rec.meta = rheomag::lumped::read_sidecar(std::string(RHEOMAG_SOURCE_DIR) +
                                           "/tests/data/diagnosis/utfsm_damper.toml");
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.005);
  for (double& i : rec.columns.at("current")) i += noise(rng);
  const auto d = rheomag::test::run_diagnosis(rec);
  rheomag::test::print_findings(d);
  EXPECT_EQ(named(d, "magnetic_hysteresis"), nullptr);
}

}  // namespace
