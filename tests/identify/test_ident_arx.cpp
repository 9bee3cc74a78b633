// ARX least squares and AIC/FPE order selection (paper 003; MATLAB arxstruc/selstruc) on data
// simulated from known ARX systems.

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <string>

#include "core/error.hpp"
#include "identify/arx.hpp"
#include "identify/black_box_fit.hpp"

using namespace rheomag::lumped;
using namespace rheomag::identify;

namespace {

/// Random binary input (+-1) held for `hold` samples: persistently exciting.
Eigen::VectorXd random_binary(std::ptrdiff_t n, int hold, unsigned seed) {
  std::mt19937 rng(seed);
  std::bernoulli_distribution coin(0.5);
  Eigen::VectorXd u(n);
  double level = 1.0;
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    if (k % hold == 0) level = coin(rng) ? 1.0 : -1.0;
    u(k) = level;
  }
  return u;
}

/// y(k) = 1.5 y(k-1) - 0.7 y(k-2) + 0.5 u(k-1) + 0.3 u(k-2) + e(k), e ~ N(0, sigma^2):
/// ARX orders na = 2, nb = 2, nk = 1 (poles 0.75 +- 0.37i).
IoData true_arx_data(std::ptrdiff_t n, double sigma, unsigned seed) {
  const Eigen::VectorXd u = random_binary(n, 3, seed);
  std::mt19937 rng(seed + 1000);
  std::normal_distribution<double> noise(0.0, sigma);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(n);
  for (std::ptrdiff_t k = 2; k < n; ++k)
    y(k) = 1.5 * y(k - 1) - 0.7 * y(k - 2) + 0.5 * u(k - 1) + 0.3 * u(k - 2) + noise(rng);
  return make_io_data(u, y, 0.01);
}

}  // namespace

// Reference: the generating coefficients. Equation-error noise is white, so least squares is
// consistent; with N = 4000 and sigma = 0.05 (output std ~ 2) the standard errors are ~1e-3,
// tolerance 0.01.
TEST(IdentArx, RecoversKnownCoefficients) {
  const ArxModel m = fit_arx(true_arx_data(4000, 0.05, 7), {2, 2, 1});
  EXPECT_NEAR(m.a()(0), -1.5, 0.01);
  EXPECT_NEAR(m.a()(1), 0.7, 0.01);
  EXPECT_NEAR(m.b()(0), 0.5, 0.01);
  EXPECT_NEAR(m.b()(1), 0.3, 0.01);
}

// Noise-free data: the model reproduces the data exactly in both modes (FIT = 100 % to 1e-6).
TEST(IdentArx, NoiseFreeSimulationAndPredictionReproduceData) {
  const IoData data = true_arx_data(500, 0.0, 3);
  const ArxModel m = fit_arx(data, {2, 2, 1});
  EXPECT_NEAR(evaluate(m, data, EvalMode::simulation).fit_percent, 100.0, 1e-6);
  EXPECT_NEAR(evaluate(m, data, EvalMode::prediction).fit_percent, 100.0, 1e-6);
}

namespace {

/// Orders chosen by `criterion` on 40 independent data sets (N = 2000, sigma = 0.1), grid
/// na 1..5, nb 1..5, nk 0..3; each choice must contain the true lags (no under-fitting).
std::map<std::string, int> chosen_orders(OrderCriterion criterion) {
  std::map<std::string, int> count;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const LagOrders o =
        rank_arx_orders(true_arx_data(2000, 0.1, seed), ArxGrid{}, criterion).front().orders;
    EXPECT_TRUE(o.na >= 2 && o.nk <= 1 && o.nk + o.nb - 1 >= 2)
        << "seed " << seed << " picked " << o.na << "," << o.nb << "," << o.nk;
    ++count[std::to_string(o.na) + "," + std::to_string(o.nb) + "," + std::to_string(o.nk)];
  }
  return count;
}

/// AIC (and FPE, asymptotically the same) is not consistent: each superfluous parameter wins
/// with probability ~P(chi2_1 > 2) = 0.16, and the grid holds many supersets of the true
/// structure, so the over-fitted picks are spread over many orders. Measured: the true 2,2,1 in
/// 21 of 40 data sets, the next most frequent order in 4. Required: the true order is picked at
/// least 14 times and at least three times as often as any other order.
void expect_true_order_dominates(const std::map<std::string, int>& count) {
  const int hits = count.count("2,2,1") ? count.at("2,2,1") : 0;
  EXPECT_GE(hits, 14);
  for (const auto& [orders, n] : count) {
    if (orders != "2,2,1") {
      EXPECT_GE(hits, 3 * n) << orders << " picked " << n << " times";
    }
  }
}

}  // namespace

TEST(IdentArx, AicPicksTrueOrder) {
  expect_true_order_dominates(chosen_orders(OrderCriterion::aic));
}

TEST(IdentArx, FpePicksTrueOrder) {
  expect_true_order_dominates(chosen_orders(OrderCriterion::fpe));
}

TEST(IdentArx, TooFewSamplesForTheOrderIsInputError) {
  EXPECT_THROW(fit_arx(true_arx_data(8, 0.1, 1), {4, 4, 1}), rheomag::InputError);
}

TEST(IdentArx, ModelNamesAreParsedAndUnknownOnesGetASuggestion) {
  EXPECT_EQ(parse_model_spec("arx:2,4,1").numbers, (std::vector<int>{2, 4, 1}));
  EXPECT_TRUE(parse_model_spec("arx:auto,fpe").fpe);
  EXPECT_THROW(parse_model_spec("arx:2,4"), rheomag::InputError);
  EXPECT_THROW(parse_model_spec("arx:2,x,1"), rheomag::InputError);
  try {
    parse_model_spec("narxx");
    FAIL() << "no error for an unknown model";
  } catch (const rheomag::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'narx"), std::string::npos) << e.what();
  }
  EXPECT_EQ(closest_model_name("boucwen", known_model_names()), "bouc-wen");
}
