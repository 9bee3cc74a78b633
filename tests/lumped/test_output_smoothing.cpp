// The recording-processing smoothing of the damper model (lumped/output_smoothing.hpp): the centred
// moving average against closed forms (a clipped ramp, a sine's sinc gain and its derivative in
// the window), the drive period, and a family fit that recovers a known window from simulated
// recordings and predicts another stroke and frequency.

#include <gtest/gtest.h>

#include <ceres/jet.h>

#include <cmath>
#include <vector>

#include "lumped/current_dependent_fit.hpp"
#include "lumped/greybox.hpp"
#include "lumped/metrics.hpp"
#include "lumped/output_smoothing.hpp"
#include "lumped/phenomenological.hpp"

using namespace rheomag::lumped;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Samples t_k = t0 + k h, k < n.
std::vector<double> times(double t0, double h, std::size_t n) {
  std::vector<double> t(n);
  for (std::size_t k = 0; k < n; ++k) t[k] = t0 + h * static_cast<double>(k);
  return t;
}

/// Centred moving average over w of sin(2 pi f t): sin(2 pi f t) sin(pi f w) / (pi f w).
double sine_average(double t, double f, double w) {
  return std::sin(2 * kPi * f * t) * std::sin(kPi * f * w) / (kPi * f * w);
}

}  // namespace

// A ramp clipped at +-1 (y = clamp(t / r, -1, 1), knots on the grid) is piecewise linear, so its
// moving average is exact: (G(t + w/2) - G(t - w/2)) / w with G(s) = s^2 / (2 r) for |s| <= r,
// |s| - r / 2 beyond. Tolerance 1e-12 (rounding).
TEST(OutputSmoothing, BoxcarOfAClippedRampIsExact) {
  const double r = 0.01, w = 0.1, h = 1e-3;
  const std::vector<double> t = times(-0.5, h, 1001);
  std::vector<double> y(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) y[k] = std::clamp(t[k] / r, -1.0, 1.0);
  centred_boxcar(t.data(), t.size(), w, y.data());
  const auto G = [&](double s) { return std::abs(s) <= r ? s * s / (2 * r) : std::abs(s) - r / 2; };
  for (std::size_t k = 100; k + 100 < t.size(); ++k)
    EXPECT_NEAR(y[k], (G(t[k] + w / 2) - G(t[k] - w / 2)) / w, 1e-12) << t[k];
  EXPECT_NEAR(y.front(), -1.0, 1e-12);  // window shrunk to nothing at the ends
  EXPECT_NEAR(y.back(), 1.0, 1e-12);
}

// A sine's moving average has the gain sin(pi f w) / (pi f w) (0.9836 for w = T / 10). The
// trapezoidal integral of the sampled sine is second order: halving the sampling step divides the
// largest error by 3.5-4.5 (4 expected), and at 100 samples per period it is below 1e-3.
TEST(OutputSmoothing, BoxcarOfASineHasTheSincGainAtSecondOrder) {
  const double f = 1.0, w = 0.1;
  const auto worst_error = [&](double h) {
    const std::vector<double> t = times(0.0, h, static_cast<std::size_t>(std::lround(4.0 / h)) + 1);
    std::vector<double> y(t.size());
    for (std::size_t k = 0; k < t.size(); ++k) y[k] = std::sin(2 * kPi * f * t[k]);
    centred_boxcar(t.data(), t.size(), w, y.data());
    double worst = 0.0;
    for (std::size_t k = 0; k < t.size(); ++k)
      if (t[k] > w && t[k] < 4.0 - w)
        worst = std::max(worst, std::abs(y[k] - sine_average(t[k], f, w)));
    return worst;
  };
  const double e1 = worst_error(0.01), e2 = worst_error(0.005);
  EXPECT_LT(e1, 1e-3);
  EXPECT_GT(e1 / e2, 3.5);
  EXPECT_LT(e1 / e2, 4.5);
}

// The window width is differentiated by Jets (the fit estimates it): d/dw of the sine's average
// against the derivative of the closed form, within 1e-4 of its scale at 1000 samples per period.
TEST(OutputSmoothing, WidthDerivativeMatchesTheClosedForm) {
  using Jet = ceres::Jet<double, 1>;
  const double f = 1.0, w = 0.1, h = 1e-3;
  const std::vector<double> t = times(0.0, h, 2001);
  std::vector<Jet> y(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) y[k] = Jet(std::sin(2 * kPi * f * t[k]));
  centred_boxcar(t.data(), t.size(), Jet(w, 0), y.data());
  const double x = kPi * f * w;
  const double dgain_dw = kPi * f * (x * std::cos(x) - std::sin(x)) / (x * x);
  for (std::size_t k = 200; k < 1800; k += 37)
    EXPECT_NEAR(y[k].v[0], std::sin(2 * kPi * f * t[k]) * dgain_dw,
                1e-4 * std::abs(dgain_dw) + 1e-6)
        << t[k];
}

// The period of a sine with an offset and a phase (0.984 s, sampled at 1 kHz, 10 cycles) within
// 1e-4 s; a drive with fewer than two full cycles or with cycles of different lengths has none.
TEST(OutputSmoothing, DrivePeriodOfSinesAndNonPeriodicDrives) {
  const double period = 0.984;
  const std::vector<double> t = times(0.0, 1e-3, 9840);
  std::vector<double> v(t.size()), chirp(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    v[k] = 0.003 + 0.05 * std::cos(2 * kPi * t[k] / period + 0.7);
    chirp[k] = std::sin(2 * kPi * (0.2 * t[k] + 0.05 * t[k] * t[k]));
  }
  EXPECT_NEAR(drive_period(t, v), period, 1e-4);
  EXPECT_EQ(drive_period(t, chirp), 0.0);
  const std::vector<double> short_t(t.begin(), t.begin() + 1500),
      short_v(v.begin(), v.begin() + 1500);
  EXPECT_EQ(drive_period(short_t, short_v), 0.0);
}

namespace {

/// A damper recording driven by x = a sin(2 pi f t) (at `current` A, `n` samples at `dt`) or, when
/// `chirp`, by a sweep from f to 3 f (no period); force column zero.
Recording sine_recording(double a, double f, double current, std::size_t n, double dt,
                         bool chirp = false) {
  Recording rec;
  std::vector<double> x, v, i;
  const double duration = dt * static_cast<double>(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = dt * static_cast<double>(k);
    const double rate = chirp ? f * (1.0 + t / duration) : f;  // phase' / (2 pi): f to 3 f
    const double phase = 2 * kPi * (chirp ? f * (t + 0.5 * t * t / duration) : f * t);
    rec.t.push_back(t);
    x.push_back(a * std::sin(phase));
    v.push_back(a * 2 * kPi * rate * std::cos(phase));
    i.push_back(current);
  }
  rec.columns["displacement"] = x;
  rec.columns["velocity"] = v;
  rec.columns["current"] = i;
  rec.columns["force"] = std::vector<double>(n, 0.0);
  rec.meta.drive = {"displacement", "velocity", "current"};
  rec.meta.output = "force";
  rec.csv_path = "synthetic.csv";
  return rec;
}

}  // namespace

// Every grey-box model carries output_smoothing (equal terms in a family comparison): a family of
// two recordings (20 mm / 0.5 Hz at 0 A and 10 mm / 1 Hz at 1 A) simulated by the model and
// smoothed over a tenth of each period, as the UTFSM tests were processed, is fitted jointly: the
// window is recovered within 5 % (0.1) and both recordings fit at FIT >= 98 %. A sweep (no drive
// period) holds the window at 0.
TEST(OutputSmoothing, EveryGreyBoxModelRecoversTheWindow) {
  struct Case {
    PhenoKind kind;
    std::vector<double> truth;  // without output_smoothing
  };
  const std::vector<Case> cases = {
      {PhenoKind::bingham, {200.0, 800.0, 1500.0, 500.0, 0.005, 0.0}},
      {PhenoKind::lugre, {150.0, 700.0, 0.5, 300.0, 120.0, 60.0, 0.7, 0.0}},
      {PhenoKind::maxwell, {0.016, 1200.0, 150.0, 600.0, 150.0, 0.0}}};
  for (const Case& c : cases) {
    std::vector<Recording> family = {sine_recording(0.02, 0.5, 0.0, 3000, 2e-3),
                                     sine_recording(0.01, 1.0, 1.0, 1500, 2e-3)};
    for (std::size_t r = 0; r < family.size(); ++r) {
      Recording& rec = family[r];
      GreyboxSetup setup = greybox_setup_for(rec, c.kind);
      setup.settings.eps = 1e-4;
      setup.settings.motion_scale = 0.06;
      rec.columns["force"] = simulate_pheno(rec, setup, c.truth);
      const double period = r == 0 ? 2.0 : 1.0;
      centred_boxcar(rec.t.data(), rec.t.size(), 0.1 * period, rec.columns["force"].data());
    }
    GreyboxOptions options;
    options.starts = 2;
    const GreyboxFit fit = fit_greybox_family(family, pheno_name(c.kind), options, 1);
    const FittedParameter& window = fit.params[pheno_smoothing_index(c.kind)];
    EXPECT_EQ(window.name, "output_smoothing");
    EXPECT_NEAR(window.value, 0.1, 0.005) << pheno_name(c.kind);
    for (const Recording& rec : family) {
      const Metrics m = compute_metrics(rec.column("force"), simulate_greybox(rec, fit),
                                        SampleRange{0, rec.t.size()});
      EXPECT_GE(m.fit_percent, 98.0) << pheno_name(c.kind);
    }
  }
  Recording sweep = sine_recording(0.01, 0.5, 1.0, 4000, 2e-3, true);
  GreyboxSetup setup = greybox_setup_for(sweep, PhenoKind::bingham);
  setup.settings.eps = 1e-4;
  setup.settings.motion_scale = 0.06;
  sweep.columns["force"] = simulate_pheno(sweep, setup, cases.front().truth);
  const GreyboxFit fit = fit_greybox(sweep, "bingham");
  const FittedParameter& window = fit.params[pheno_smoothing_index(PhenoKind::bingham)];
  EXPECT_TRUE(window.fixed);
  EXPECT_EQ(window.value, 0.0);
}
