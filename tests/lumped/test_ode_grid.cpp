// The fixed-grid SDIRK2 integrator (lumped/ode_grid.hpp) and the chamber's volume law: order of
// convergence, L-stability on a stiff lag, agreement with the error-controlled rosenbrock4 on a
// compliant rig with many current edges, and stored_volume / pressure_at / capacitance consistent.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "lumped/blocks.hpp"
#include "lumped/ode_grid.hpp"
#include "lumped/rig_model.hpp"
#include "lumped/signals.hpp"
#include "tests/lumped/bypass_rig.hpp"

using namespace rheomag::lumped;

namespace {

/// x' = (sin(w t) - x) / tau: a first-order lag driven by a sine (exact solution known).
class SineLag : public OdeSystem {
 public:
  SineLag(double tau, double w) : tau_(tau), w_(w) {}
  std::size_t state_size() const override { return 1; }
  void derivatives(double t, const double* x, double* dxdt) const override {
    dxdt[0] = (std::sin(w_ * t) - x[0]) / tau_;
  }
  std::vector<double> state_scales() const override { return {1.0}; }
  /// Exact solution from x(0) = 0.
  double exact(double t) const {
    const double a = w_ * tau_, d = 1.0 + a * a;
    return (std::sin(w_ * t) - a * std::cos(w_ * t) + a * std::exp(-t / tau_)) / d;
  }

 private:
  double tau_, w_;
};

double max_error(const SineLag& sys, double h) {
  std::vector<double> t;
  for (int k = 0; k * h <= 1.0 + 1e-12; ++k) t.push_back(k * h);
  const auto x = integrate_on_grid(sys, {0.0}, t);
  double err = 0.0;
  for (std::size_t k = 0; k < t.size(); ++k)
    err = std::max(err, std::abs(x[k][0] - sys.exact(t[k])));
  return err;
}

RigSpec compliant_bypass() {
  RigSpec s = rheomag::test::bypass_rig();
  s.compressibility = ChamberBlock{5e-5, 1.5e9, 2e-7, 1e5, 1.0};
  s.mr_response_time = 0.01;
  return s;
}

/// rms difference of the pressure between one grid step per sample and rosenbrock4, over the
/// rms pressure, for `s` driven through 40 current steps at 1 kHz.
double grid_against_adaptive(RigSpec s) {
  Recording d;
  d.t = uniform_times(4.0, 1e3);
  add_signal(d, "displacement=sine:amplitude=0.025,frequency=0.7");
  add_signal(d, "current=steps:levels=0/1,period=0.1");
  const auto adaptive = simulate_rig(s, d).column("pressure");
  s.grid_substeps = 1;
  const auto grid = simulate_rig(s, d).column("pressure");
  double err = 0.0, rms = 0.0;
  for (std::size_t k = 0; k < grid.size(); ++k) {
    err += (grid[k] - adaptive[k]) * (grid[k] - adaptive[k]);
    rms += adaptive[k] * adaptive[k];
  }
  return std::sqrt(err / rms);
}

}  // namespace

// SDIRK2 is second order: halving the step divides the maximum error by 2^2 = 4 (measured ratio
// within 0.2 of order 2 on a lag tau = 0.1 s driven at 10 rad/s, steps 10 ms -> 1.25 ms).
TEST(OdeGrid, SecondOrderConvergence) {
  const SineLag sys(0.1, 10.0);
  const double e1 = max_error(sys, 0.01), e2 = max_error(sys, 0.005), e3 = max_error(sys, 0.0025);
  std::cout << "max errors " << e1 << " " << e2 << " " << e3 << "\n";
  EXPECT_NEAR(std::log2(e1 / e2), 2.0, 0.2);
  EXPECT_NEAR(std::log2(e2 / e3), 2.0, 0.2);
  EXPECT_LT(e3, 1e-4);
}

// L-stability: a lag 1e5 times faster than the step follows the quasi-static value sin(w t)
// (error O(tau) = 1e-8 relative) with no oscillation, where an explicit step would blow up.
TEST(OdeGrid, StiffLagIsQuasiStatic) {
  const SineLag sys(1e-8, 10.0);
  std::vector<double> t;
  for (int k = 0; k <= 100; ++k) t.push_back(k * 1e-3);
  const auto x = integrate_on_grid(sys, {0.0}, t);
  for (std::size_t k = 2; k < t.size(); ++k) ASSERT_NEAR(x[k][0], std::sin(10.0 * t[k]), 1e-6);
}

// The chamber law: pressure_at inverts stored_volume to 1e-12 relative (isothermal closed form
// and adiabatic Newton), and capacitance is its derivative (central difference, 1e-6 relative).
TEST(OdeGrid, ChamberVolumeLawIsConsistent) {
  for (double n : {1.0, 1.4}) {
    const ChamberBlock c{5e-5, 1.5e9, 2e-7, 1e5, n};
    for (double p : {2e3, 5e4, 1e5, 1e6, 2e7}) {
      EXPECT_NEAR(c.pressure_at(c.stored_volume(p)), p, 1e-12 * p) << "n " << n;
      const double d = 1e-6 * p;
      const double fd = (c.stored_volume(p + d) - c.stored_volume(p - d)) / (2 * d);
      EXPECT_NEAR(c.capacitance(p), fd, 1e-6 * fd) << "n " << n << " p " << p;
    }
    EXPECT_EQ(c.stored_volume(1e5), 0.0);
    // Far below the precharge the air takes the volume: the pressure stays positive.
    EXPECT_GT(c.pressure_at(-10 * 2e-7), 0.0);
  }
}

// A compliant bypass rig (2e-7 m^3 of air, 10 ms MR lag) driven through 40 current steps at 1 kHz:
// one grid step per sample (8 in the intervals of the current steps, as the diagnosis runs it)
// stays within 0.5 % rms (of the pressure's rms) of the error-controlled rosenbrock4 (tolerance
// 1e-6).
TEST(OdeGrid, RigAgreesWithAdaptiveIntegrator) {
  const double diff = grid_against_adaptive(compliant_bypass());
  std::cout << "rms difference / rms " << diff << "\n";
  EXPECT_LT(diff, 5e-3);
}

// Compliance plus inertance (5e5 Pa s^2/m^3) ring at about 1 kHz (omega = 1 / sqrt(L C), C the
// chamber capacitance at 1 MPa), omega h = 6 at 1 kHz sampling: one step per sample would damp
// the ringing away, so such a spec takes 8 steps in every interval. Within 3 % rms of rosenbrock4.
TEST(OdeGrid, RingingChambersTakeEightSteps) {
  RigSpec s = compliant_bypass();
  s.inertance = 5e5;
  const double diff = grid_against_adaptive(s);
  std::cout << "rms difference / rms " << diff << "\n";
  EXPECT_LT(diff, 3e-2);
}
