// Simulation-stability check of black-box models: the largest root of a polynomial against its
// known roots, and the verdict on models whose free run diverges, explodes or stays bounded.

#include <gtest/gtest.h>

#include <cmath>

#include "identify/stability.hpp"

using namespace rheomag::identify;

namespace {

/// A stand-in model whose free run is y(k) = g y(k-1) + u(k): stable for |g| < 1; it names itself
/// "arx:1,1,0" with a1 = -g so the pole check applies.
class FirstOrder : public IdentModel {
 public:
  explicit FirstOrder(double g) : g_(g) {}
  std::string name() const override { return "arx:1,1,0"; }
  std::vector<NamedValue> params() const override { return {{"a1", -g_}, {"b1", 1.0}}; }
  std::ptrdiff_t warmup() const override { return 1; }
  Eigen::VectorXd run(const IoData& data, EvalMode) const override {
    Eigen::VectorXd y(data.size());
    y(0) = data.y(0);
    for (Eigen::Index k = 1; k < data.size(); ++k) y(k) = g_ * y(k - 1) + data.u(k, 0);
    return y;
  }

 private:
  double g_;
};

IoData sine_data() {
  IoData d;
  d.u.resize(400, 1);
  d.y.resize(400);
  for (Eigen::Index k = 0; k < 400; ++k) {
    d.u(k, 0) = std::sin(0.05 * static_cast<double>(k));
    d.y(k) = 0.5 * d.u(k, 0);
  }
  return d;
}

}  // namespace

// (z - 0.5)(z + 2)(z^2 + 0.25) = z^4 + 1.5 z^3 - 0.75 z^2 + 0.375 z - 0.25: largest |root| = 2.
TEST(IdentStability, LargestRootModulusOfAKnownPolynomial) {
  EXPECT_NEAR(largest_root_modulus({1.5, -0.75, 0.375, -0.25}), 2.0, 1e-12);
  EXPECT_NEAR(largest_root_modulus({0.0, 0.25}), 0.5, 1e-12);  // z^2 + 0.25: |z| = 0.5
  EXPECT_EQ(largest_root_modulus({}), 0.0);
}

// g = 0.5: pole 0.5, gain ~2 against the measured 0.5 (peak ratio ~4): stable. g = 1.02: pole
// outside the unit circle and the free run grows without bound over 400 samples: unstable, both
// reasons named.
TEST(IdentStability, FlagsAPoleOutsideTheUnitCircleAndARunaway) {
  const IoData d = sine_data();
  const StabilityVerdict ok = check_simulation_stability(FirstOrder(0.5), d);
  EXPECT_TRUE(ok.stable) << ok.reason;
  ASSERT_TRUE(ok.pole_radius.has_value());
  EXPECT_NEAR(*ok.pole_radius, 0.5, 1e-12);
  EXPECT_LT(ok.peak_ratio, 5.0);
  const StabilityVerdict bad = check_simulation_stability(FirstOrder(1.02), d);
  EXPECT_FALSE(bad.stable);
  EXPECT_NE(bad.reason.find("unit circle"), std::string::npos) << bad.reason;
  EXPECT_NE(bad.reason.find("times the measured peak"), std::string::npos) << bad.reason;
}

// A pole just inside the unit circle that still amplifies the input beyond 10x the measured peak
// (gain ~20 at this frequency against the measured 0.5) is flagged by the bounded-response test
// alone.
TEST(IdentStability, FlagsAnUnboundedLookingResponseWithStablePoles) {
  const StabilityVerdict v = check_simulation_stability(FirstOrder(0.999), sine_data());
  EXPECT_FALSE(v.stable);
  EXPECT_EQ(v.reason.find("unit circle"), std::string::npos) << v.reason;
}
