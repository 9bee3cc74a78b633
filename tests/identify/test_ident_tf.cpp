// Continuous transfer-function estimation (tfest-like) and its zero-order-hold simulation.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "identify/black_box_fit.hpp"
#include "identify/tf_estimation.hpp"

using namespace rheomag::lumped;
using namespace rheomag::identify;

namespace {

/// G(s) = K wn^2 / (s^2 + 2 zeta wn s + wn^2) with K = 2, wn = 20 rad/s, zeta = 0.3.
ContinuousTf second_order() {
  return ContinuousTf{Eigen::VectorXd::Constant(1, 2.0 * 400.0), Eigen::Vector2d(12.0, 400.0)};
}

/// Pseudo-random binary input (+-1) held 10 samples.
Eigen::VectorXd prbs(std::ptrdiff_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::bernoulli_distribution coin(0.5);
  Eigen::VectorXd u(n);
  double level = 1.0;
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    if (k % 10 == 0) level = coin(rng) ? 1.0 : -1.0;
    u(k) = level;
  }
  return u;
}

Eigen::VectorXd with_noise(Eigen::VectorXd y, double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  for (auto& v : y) v += noise(rng);
  return y;
}

}  // namespace

// Reference: first-order lag K/(tau s + 1) under a step is K (1 - exp(-t/tau)); the ZOH
// discretisation is exact for a step, so agreement to 1e-12 at every sample.
TEST(IdentTf, ZohSimulationOfFirstOrderLagMatchesAnalyticStep) {
  const double tau = 0.05, gain = 3.0, h = 0.002;
  const ContinuousTf g{Eigen::VectorXd::Constant(1, gain / tau),
                       Eigen::VectorXd::Constant(1, 1.0 / tau)};
  const Eigen::VectorXd y = simulate_tf(g, Eigen::VectorXd::Ones(200), h);
  for (int k = 0; k < 200; ++k) EXPECT_NEAR(y(k), gain * (1.0 - std::exp(-k * h / tau)), 1e-12);
}

// Reference: the generating G. PRBS input, Ts = 5 ms, N = 2000, white output noise
// sigma = 0.05 (output std ~ 1.4, SNR ~ 29 dB). Coefficients must come back within 2 %
// (standard errors are ~0.3 %); the fit must be stable.
TEST(IdentTf, RecoversSecondOrderSystemFromNoisyPrbsResponse) {
  const double h = 0.005;
  const Eigen::VectorXd u = prbs(2000, 11);
  const Eigen::VectorXd y = with_noise(simulate_tf(second_order(), u, h), 0.05, 12);
  const TfModel m = fit_tf(make_io_data(u, y, h), 2, 0);
  ASSERT_TRUE(m.tf().stable());
  EXPECT_NEAR(m.tf().den(0), 12.0, 0.02 * 12.0);
  EXPECT_NEAR(m.tf().den(1), 400.0, 0.02 * 400.0);
  EXPECT_NEAR(m.tf().num(0), 800.0, 0.02 * 800.0);
}

// Step response (a weaker excitation) from a non-zero initial state x0 = (0.5, 0), noise
// sigma = 0.02: DC gain and natural frequency within 3 %; the initial state is estimated.
TEST(IdentTf, RecoversSecondOrderSystemFromNoisyStepResponse) {
  const double h = 0.005;
  const Eigen::VectorXd u = Eigen::VectorXd::Ones(600);
  const Eigen::VectorXd y =
      with_noise(simulate_tf(second_order(), u, h, Eigen::Vector2d(0.5 / 800.0, 0.0)), 0.02, 5);
  const TfModel m = fit_tf(make_io_data(u, y, h), 2, 0);
  EXPECT_NEAR(m.tf().dc_gain(), 2.0, 0.03 * 2.0);
  EXPECT_NEAR(std::sqrt(m.tf().den(1)), 20.0, 0.03 * 20.0);
}

// tf:auto (AIC over np <= 4, nz < np) must pick the true structure (2 poles, no zero) on the
// PRBS data above: extra poles/zeros only fit noise there.
TEST(IdentTf, AutoPicksTrueOrder) {
  const double h = 0.005;
  const Eigen::VectorXd u = prbs(2000, 21);
  const Eigen::VectorXd y = with_noise(simulate_tf(second_order(), u, h), 0.05, 22);
  const TfModel m = fit_tf_auto(make_io_data(u, y, h), 3);
  EXPECT_EQ(m.name(), "tf:2,0");
}

TEST(IdentTf, BadOrdersAreInputErrors) {
  const IoData d = make_io_data(prbs(500, 1), prbs(500, 2), 0.01);
  EXPECT_THROW(fit_tf(d, 2, 2), rheomag::InputError);
  EXPECT_THROW(fit_tf(d, 0, 0), rheomag::InputError);
  EXPECT_THROW(fit_tf(make_io_data(prbs(20, 1), prbs(20, 2), 0.01), 3, 1), rheomag::InputError);
}
