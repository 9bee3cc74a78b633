// Nonlinear black-box models (polynomial NARX, Hammerstein-Wiener, SVR-NARX) against linear ARX
// on a simulated Wiener system, and the building blocks they rely on.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "identify/arx.hpp"
#include "identify/black_box_fit.hpp"
#include "identify/hammerstein_wiener.hpp"
#include "identify/narx.hpp"
#include "identify/svr.hpp"

using namespace rheomag::lumped;
using namespace rheomag::identify;

namespace {

/// Wiener system: x(k+1) = 0.8 x(k) + 0.2 u(k), y(k) = tanh(2.5 x(k)) + e(k), e ~ N(0, 0.02^2);
/// u is a random level in [-1, 1] held 8 samples. A saturating static output map, like an MR
/// damper's force-velocity curve, which no linear model can follow.
IoData wiener_data(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> level(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.02);
  Eigen::VectorXd u(n), y(n);
  double x = 0.0, held = 0.0;
  for (int k = 0; k < n; ++k) {
    if (k % 8 == 0) held = level(rng);
    u(k) = held;
    y(k) = std::tanh(2.5 * x) + noise(rng);
    x = 0.8 * x + 0.2 * u(k);
  }
  return make_io_data(u, y, 0.01);
}

double validation_fit(const IdentModel& m, const IoData& validation) {
  return evaluate(m, validation, EvalMode::simulation).fit_percent;
}

class NonlinearVersusArx : public ::testing::Test {
 protected:
  void SetUp() override {
    const IoData all = wiener_data(1500, 3);
    train = slice(all, 0, 1000);
    validation = slice(all, 1000, 1500);
    const LagOrders best = rank_arx_orders(train, ArxGrid{}, OrderCriterion::aic).front().orders;
    arx_fit = validation_fit(fit_arx(train, best), validation);
  }
  IoData train, validation;
  double arx_fit = 0.0;
};

}  // namespace

// Measured (seed 3): arx:auto 79.2 %, narx 95.9 %, hw 92.6 %, svr 96.0 % validation FIT in
// simulation. Each nonlinear model must beat the best linear ARX by at least 8 points and reach
// 88 % (the noise floor is ~97 %).
TEST_F(NonlinearVersusArx, PolynomialNarxBeatsArx) {
  NarxOptions options;
  options.orders = {2, 2, 1};
  const double fit = validation_fit(fit_narx(train, options), validation);
  EXPECT_GT(fit, arx_fit + 8.0);
  EXPECT_GT(fit, 88.0);
}

TEST_F(NonlinearVersusArx, HammersteinWienerBeatsArx) {
  const double fit = validation_fit(fit_hw(train, HwOptions{1, 1, 1, 8}), validation);
  EXPECT_GT(fit, arx_fit + 8.0);
  EXPECT_GT(fit, 88.0);
}

TEST_F(NonlinearVersusArx, SvrNarxBeatsArx) {
  SvrSearch search;
  search.lags = {{1, 1, 1}, {2, 2, 1}};
  search.c = {10.0, 100.0};
  search.gamma = {0.5, 2.0};
  search.epsilon = {0.02};
  const double fit = validation_fit(fit_svr(train, search), validation);
  EXPECT_GT(fit, arx_fit + 8.0);
  EXPECT_GT(fit, 88.0);
}

// Reference: a polynomial NARX containing the true terms. y(k) = 0.5 y(k-1) + u(k-1)
// - 0.3 u(k-1)^3 without noise: FROLS must select exactly these terms first and least squares
// must return the coefficients to 1e-8.
TEST(IdentNarx, FrolsFindsTheTrueTermsOfAPolynomialSystem) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> level(-1.0, 1.0);
  const int n = 600;
  Eigen::VectorXd u(n), y = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < n; ++k) u(k) = level(rng);
  for (int k = 1; k < n; ++k) y(k) = 0.5 * y(k - 1) + u(k - 1) - 0.3 * std::pow(u(k - 1), 3);
  NarxOptions options;
  options.orders = {1, 1, 1};
  options.degree = 3;
  const NarxModel m = fit_narx(make_io_data(u, y, 1.0), options);
  EXPECT_NEAR(evaluate(m, make_io_data(u, y, 1.0), EvalMode::simulation).fit_percent, 100.0, 1e-6);
}

TEST(IdentNarx, MonomialCountIsTheBinomial) {
  // Monomials of degree <= 3 in 6 variables: C(6 + 3, 3) = 84 (including the constant).
  EXPECT_EQ(all_monomials(6, 3).size(), 84u);
}

TEST(IdentHw, PiecewiseLinearInterpolatesAndExtrapolates) {
  const PiecewiseLinear f{Eigen::Vector3d(0.0, 1.0, 3.0), Eigen::Vector3d(0.0, 2.0, 3.0)};
  EXPECT_DOUBLE_EQ(f(0.5), 1.0);
  EXPECT_DOUBLE_EQ(f(2.0), 2.5);
  EXPECT_DOUBLE_EQ(f(-1.0), -2.0);  // first segment's slope 2
  EXPECT_DOUBLE_EQ(f(5.0), 4.0);    // last segment's slope 0.5
}

TEST(IdentHw, MultipleDrivesAreRejected) {
  IoData d = wiener_data(400, 1);
  d.u.conservativeResize(Eigen::NoChange, 2);
  d.u.col(1).setOnes();
  EXPECT_THROW(fit_hw(d), rheomag::InputError);
}

// narx on a constant output died with SIGSEGV inside the QR of an empty regressor matrix.
TEST(BadInputRecording, NarxOnConstantOutputIsInputError) {
  IoData data;
  const int n = 400;
  data.u.resize(n, 1);
  for (int k = 0; k < n; ++k) data.u(k, 0) = std::sin(0.1 * k);
  data.y = Eigen::VectorXd::Constant(n, 5.0);
  data.sample_time = 0.005;
  NarxOptions options;
  options.orders = {2, 2, 1};
  EXPECT_THAT([&] { fit_narx(data, options); },
              ::testing::ThrowsMessage<rheomag::InputError>(
                  ::testing::HasSubstr("narx: the output is constant (5 on all 400 samples)")));
}
