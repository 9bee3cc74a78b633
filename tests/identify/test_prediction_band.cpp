// The band of a prediction (identify/prediction_band.hpp) against the closed form of a model linear
// in the uncertain parameters: Bingham's output is F = (F_y + F_b I) tanh(v / v_t) + (c + c_b I) v
// + f_0, so with a covariance on F_y and c only, the band at sample i is
// sqrt(s_y^2 tanh_i^2 + 2 rho s_y s_c tanh_i v_i + s_c^2 v_i^2), tanh_i = tanh(v_i / v_t), exactly
// (forward differences of a linear output are exact up to round-off: tolerance 1e-6 relative; the
// correlation term is 28 % of the variance, so a band that ignored it would fail).

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "identify/greybox.hpp"
#include "identify/prediction_band.hpp"
#include "lumped/phenomenological.hpp"

using namespace rheomag::lumped;
using namespace rheomag::identify;

namespace {

/// A 3 s Bingham damper test: 20 mm at 0.7 Hz, 0.5 A, 500 Hz, force from `fit` (offset 30 N,
/// so its mean is not zero and nothing is mean-removed).
Recording bingham_recording(GreyboxFit& fit) {
  Recording rec;
  const double pi = std::acos(-1.0);
  std::vector<double> x, v;
  for (int k = 0; k < 1500; ++k) {
    const double t = k * 2e-3;
    rec.t.push_back(t);
    x.push_back(0.02 * std::sin(2 * pi * 0.7 * t));
    v.push_back(0.02 * 2 * pi * 0.7 * std::cos(2 * pi * 0.7 * t));
  }
  rec.columns["displacement"] = x;
  rec.columns["velocity"] = v;
  rec.columns["current"] = std::vector<double>(x.size(), 0.5);
  rec.columns["force"] = std::vector<double>(x.size(), 0.0);
  rec.meta.drive = {"displacement", "velocity", "current"};
  rec.meta.output = "force";
  fit.model = "bingham";
  fit.setup = greybox_setup_for(rec, PhenoKind::bingham);
  fit.setup.settings.eps = 1e-4;
  fit.setup.settings.motion_scale = 0.06;
  const std::vector<double> values = {200.0, 800.0, 1500.0, 500.0, 0.005, 30.0, 0.0};
  for (std::size_t k = 0; k < values.size(); ++k) {
    FittedParameter p;
    p.name = pheno_params(PhenoKind::bingham)[k].name;
    p.value = values[k];
    fit.params.push_back(p);
  }
  rec.columns["force"] = simulate_greybox(rec, fit);
  return rec;
}

}  // namespace

TEST(PredictionBand, MatchesTheClosedFormOfALinearModel) {
  GreyboxFit fit;
  const Recording rec = bingham_recording(fit);
  const double s_y = 40.0, s_c = 3000.0, rho = -0.6;  // yield [N], viscous [N s/m]
  const int fy = pheno_param_index(PhenoKind::bingham, "yield");
  const int c = pheno_param_index(PhenoKind::bingham, "viscous");
  fit.covariance_between_recordings = Eigen::MatrixXd::Zero(7, 7);
  fit.covariance_between_recordings(fy, fy) = s_y * s_y;
  fit.covariance_between_recordings(c, c) = s_c * s_c;
  fit.covariance_between_recordings(fy, c) = fit.covariance_between_recordings(c, fy) =
      rho * s_y * s_c;
  const auto band = prediction_band(rec, fit);
  ASSERT_TRUE(band.has_value());
  const std::vector<double>& v = rec.column("velocity");
  const std::vector<double>& y = rec.column("force");
  double variance = 0.0, correlated = 0.0, mean = 0.0, spread = 0.0;
  for (double vi : v) {
    const double th = std::tanh(vi / 0.005);
    variance +=
        (s_y * s_y * th * th + 2 * rho * s_y * s_c * th * vi + s_c * s_c * vi * vi) / v.size();
    correlated += 2 * rho * s_y * s_c * th * vi / v.size();
  }
  EXPECT_GT(std::abs(correlated), 0.25 * variance);
  for (double yi : y) mean += yi / y.size();
  for (double yi : y) spread += (yi - mean) * (yi - mean) / y.size();
  EXPECT_NEAR(band->rms, std::sqrt(variance), 1e-6 * std::sqrt(variance));
  EXPECT_NEAR(band->percent, 100.0 * std::sqrt(variance / spread), 1e-6 * band->percent);

  // A parameter on a bound is left out (its error is not two-sided): only the viscous term.
  fit.params[static_cast<std::size_t>(fy)].at_bound = true;
  const auto without_yield = prediction_band(rec, fit);
  ASSERT_TRUE(without_yield.has_value());
  double viscous_only = 0.0;
  for (double vi : v) viscous_only += s_c * s_c * vi * vi / v.size();
  EXPECT_NEAR(without_yield->rms, std::sqrt(viscous_only), 1e-6 * std::sqrt(viscous_only));

  // No covariance (a fit on one recording): no band.
  fit.covariance_between_recordings.resize(0, 0);
  EXPECT_FALSE(prediction_band(rec, fit).has_value());
}
