// Transient eddy currents in a conducting cylinder in a long solenoid: step responses against
// the analytic series, the energy balance, the time-step order and a saturating step.

#include <gtest/gtest.h>

#include <cmath>

#include "magnetostatics/solver.hpp"
#include "tests/transient/cylinder.hpp"
#include "transient/transient_solver.hpp"

namespace {

using namespace rheomag;
using transient::Drive;
using transient::TimeScheme;
using transient::TransientOptions;
using transient::TransientSolver;

struct StepRun {
  transient::TransientResult result;
  std::vector<double> cylinder_flux;  // 2 pi a A(a) per recorded state [Wb]
};

StepRun simulate(const test::Cylinder& c, const cases::Problem& problem, const mesh::Mesh& mesh,
                 const TransientOptions& options,
                 std::vector<transient::RegionEddy> remedies = {}) {
  magnetostatics::MagnetostaticSolver statics(problem, mesh);
  TransientSolver solver(statics, transient::eddy_coefficients(statics.problem(), remedies));
  int surface = -1;
  for (int k = 0; k < static_cast<int>(mesh.nodes.size()); ++k)
    if (std::abs(mesh.nodes[k].r - c.a) < 1e-12 && mesh.nodes[k].z == 0.0) surface = k;
  StepRun out;
  out.result = solver.run(options, [&](const transient::TransientState& s) {
    out.cylinder_flux.push_back(2.0 * std::numbers::pi * c.a * s.a[surface]);
  });
  return out;
}

// A 1 V step through 0.2 Ohm (5 A final; smooth in time after t = 0, unlike a current step
// whose sqrt(t) start dominates any time-step error sum).
TransientOptions voltage_step(double duration) {
  TransientOptions o;
  o.drive = Drive::voltage;
  o.value = 1.0;
  o.resistance = 0.2;
  o.duration = duration;
  return o;
}

TransientOptions current_step(double duration) {
  TransientOptions o;
  o.drive = Drive::current;
  o.value = 1.0;
  o.duration = duration;
  return o;
}

// Reference: Phi(t) = Phi_inf [1 - sum 4/j_n^2 exp(-j_n^2 t / (mu sigma a^2))]; tau_1 = 108.6 ms
// for mu_r = 1000, sigma = 5 MS/m, a = 10 mm. Tolerance 1 % on t63 and t90 (the issue's), met
// here with 0.2 % margin by a 24-element graded P2 mesh and the adaptive midpoint scheme.
TEST(TransientCylinder, CurrentStepRiseTimesMatchTheSeries) {
  const test::Cylinder c;
  EXPECT_NEAR(c.tau1(), 0.1086, 0.0001);
  const StepRun r = simulate(c, c.problem(), c.mesh(24), current_step(0.5));
  const double t63 = c.time_to(1.0 - std::exp(-1.0)), t90 = c.time_to(0.9);
  ASSERT_TRUE(r.result.t63 && r.result.t90);
  std::cout << "t63 " << *r.result.t63 << " (series " << t63 << "), t90 " << *r.result.t90
            << " (series " << t90 << "), " << r.result.steps << " steps\n";
  EXPECT_NEAR(*r.result.t63 / t63, 1.0, 0.01) << *r.result.t63 << " vs " << t63;
  EXPECT_NEAR(*r.result.t90 / t90, 1.0, 0.01) << *r.result.t90 << " vs " << t90;
  // The cylinder's own flux, sampled against the series over the run (1 % of Phi_inf).
  const double phi_inf = kMu0 * c.mu_r * c.turns / c.length * std::numbers::pi * c.a * c.a;
  EXPECT_NEAR(r.cylinder_flux.back() / phi_inf, c.relative_flux(0.5), 2e-3);
  for (std::size_t k = 2; k < r.result.time.size(); ++k) {
    const double t = r.result.time[k];
    if (t < 0.1 * c.tau1()) continue;
    EXPECT_NEAR(r.cylinder_flux[k] / phi_inf, c.relative_flux(t), 0.01) << "t = " << t;
  }
}

// Right after a current step the flux enters the cylinder as sqrt(t); the first steps run before
// the error estimate has its three points and the midpoint rule does not damp their error.
// Reference: the series; from 0.1 % of tau_1 on, the cylinder's flux stays within 2e-5 of Phi_inf
// at tolerance 1e-5 (measured 7.6e-6, at 0.28 s; the earlier first step, 1e-4 of the duration,
// left 9.2e-5 at 0.13 ms).
TEST(TransientCylinder, FluxRightAfterACurrentStepFollowsTheSeries) {
  const test::Cylinder c;
  TransientOptions o = current_step(0.5);
  o.tolerance = 1e-5;
  const StepRun r = simulate(c, c.problem(), c.mesh(24), o);
  const double phi_inf = kMu0 * c.mu_r * c.turns / c.length * std::numbers::pi * c.a * c.a;
  double worst = 0.0, worst_t = 0.0;
  for (std::size_t k = 2; k < r.result.time.size(); ++k) {
    const double t = r.result.time[k];
    const double error = std::abs(r.cylinder_flux[k] / phi_inf - c.relative_flux(t));
    if (t >= 0.001 * c.tau1() && error > worst) worst = error, worst_t = t;
  }
  EXPECT_LT(worst, 2e-5) << "at t = " << worst_t << " s";
}

// Energy balance: source energy = dW + eddy loss + copper loss at every step. The midpoint
// (cG(1)) scheme satisfies it exactly up to the Newton tolerance (1e-8 of the residual) for a
// linear material; the issue asks 1e-6 relative.
TEST(TransientCylinder, EnergyBalanceOfAVoltageStep) {
  const test::Cylinder c;
  TransientOptions o;
  o.drive = Drive::voltage;
  o.value = 1.0;
  o.resistance = 0.2;
  o.duration = 0.6;
  const StepRun r = simulate(c, c.problem(), c.mesh(16), o);
  const auto& e = r.result.energy;
  std::cout << "energy balance: worst step " << e.max_step_error << ", total " << e.total_error
            << "\n";
  EXPECT_LT(e.max_step_error, 1e-6);
  EXPECT_NEAR(e.source, e.stored_change + e.eddy_loss + e.copper_loss, 1e-6 * e.source);
  EXPECT_GT(e.eddy_loss, 0.01 * e.source);        // the eddy currents do take a share
  EXPECT_DOUBLE_EQ(r.result.final_current, 5.0);  // V / R
  EXPECT_GT(r.result.current.back(), 0.9 * 5.0);  // 0.4 s is about 4 L/R
}

// Backward Euler: the scheme's identity source = field work + losses still holds per step to
// the Newton tolerance (1e-6 asked), but its field work R(A1) . dA exceeds dW: a numerical
// dissipation >= 0 of order h, reported as its own term. It must be visible (> 1e-4 of the
// run's energy at 20 steps) and halve with the step (order 1 +- 0.3 over 20/40/80 steps).
TEST(TransientCylinder, BackwardEulerDissipatesNumerically) {
  const test::Cylinder c;
  const auto problem = c.problem();
  const auto mesh = c.mesh(12);
  auto run = [&](int steps) {
    TransientOptions o = voltage_step(0.2);
    o.scheme = TimeScheme::backward_euler;
    o.steps = steps;
    return simulate(c, problem, mesh, o).result.energy;
  };
  const auto e20 = run(20), e40 = run(40), e80 = run(80);
  std::cout << "backward Euler dissipation " << e20.numerical_dissipation << " "
            << e40.numerical_dissipation << " " << e80.numerical_dissipation << " J\n";
  EXPECT_LT(e20.max_step_error, 1e-6);
  EXPECT_GT(e20.max_step_dissipation, 1e-4);
  EXPECT_GT(e20.numerical_dissipation, 0.0);
  const double order = 0.5 * (std::log2(e20.numerical_dissipation / e40.numerical_dissipation) +
                              std::log2(e40.numerical_dissipation / e80.numerical_dissipation));
  EXPECT_NEAR(order, 1.0, 0.3);
}

// Measured order of the time discretisation: lambda at t = 0.1 s after a 1 V step (R = 0.2 Ohm)
// with N = 20, 40, 80 equal steps
// against N = 1280 on the same mesh. Expected: 2 for the midpoint scheme, 1 for backward Euler
// (tolerance +-0.3 on the observed order).
double observed_order(TimeScheme scheme) {
  const test::Cylinder c;
  const auto problem = c.problem();
  const auto mesh = c.mesh(12);
  auto lambda = [&](int steps) {
    TransientOptions o;
    o.drive = Drive::voltage;
    o.value = 1.0;
    o.resistance = 0.2;
    o.duration = 0.1;
    o.scheme = scheme;
    o.steps = steps;
    return simulate(c, problem, mesh, o).result.flux_linkage.back();
  };
  const double reference = lambda(1280);
  const double e1 = std::abs(lambda(20) - reference), e2 = std::abs(lambda(40) - reference),
               e3 = std::abs(lambda(80) - reference);
  std::cout << "errors " << e1 << " " << e2 << " " << e3 << "\n";
  return 0.5 * (std::log2(e1 / e2) + std::log2(e2 / e3));
}

TEST(TransientCylinder, MidpointIsSecondOrderInTime) {
  EXPECT_NEAR(observed_order(TimeScheme::midpoint), 2.0, 0.3);
}

TEST(TransientCylinder, BackwardEulerIsFirstOrderInTime) {
  EXPECT_NEAR(observed_order(TimeScheme::backward_euler), 1.0, 0.3);
}

}  // namespace

namespace {

// Remedies. Laminated (sheets of thickness d, no macroscopic azimuthal path): the homogenised
// model H = nu B + kappa dB/dt with kappa = sigma d^2 / 12 makes B uniform in the cylinder and
// B(t) = mu H0 (1 - exp(-t / tau)), tau = mu sigma d^2 / 12 (here 0.131 ms), so t63 = tau and
// t90 = tau ln 10 exactly; 1 % tolerance (time stepping only).
TEST(TransientCylinder, LaminatedCoreFollowsItsSheetTimeConstant) {
  const test::Cylinder c;
  const double d = 0.5e-3, tau = kMu0 * c.mu_r * c.sigma * d * d / 12.0;
  transient::RegionEddy laminated{"cylinder", transient::EddyModel::laminated, 1.0, d};
  const StepRun r = simulate(c, c.problem(), c.mesh(8), current_step(6.0 * tau), {laminated});
  ASSERT_TRUE(r.result.t63 && r.result.t90);
  EXPECT_NEAR(*r.result.t63 / tau, 1.0, 0.01);
  EXPECT_NEAR(*r.result.t90 / (tau * std::log(10.0)), 1.0, 0.01);
  EXPECT_LT(r.result.energy.max_step_error, 1e-6);
}

// Slotted with factor f: sigma f, so every time constant scales by f (diffusion time
// mu sigma a^2); t63 against the series at sigma f, 1 %.
TEST(TransientCylinder, SlotFactorScalesTheEddyTimeConstant) {
  test::Cylinder c;
  transient::RegionEddy slotted{"cylinder", transient::EddyModel::slotted, 0.25, 0.0};
  const StepRun r = simulate(c, c.problem(), c.mesh(24), current_step(0.15), {slotted});
  c.sigma *= 0.25;
  ASSERT_TRUE(r.result.t63);
  EXPECT_NEAR(*r.result.t63 / c.time_to(1.0 - std::exp(-1.0)), 1.0, 0.01);
}

// Nonlinear: a saturating step (H0 = 20 kA/m at the surface of an AISI-1010-like cylinder: a
// saturation front moves inwards). Reference: 48 elements and tolerance 1e-6; the default-like
// run (24 elements, tolerance 1e-4) must give t63 and t90 within 1 % of it.
TEST(TransientCylinder, SaturatingStepAgreesWithAFineReference) {
  const test::Cylinder c;
  const auto& bh = test::kSaturatingBh;
  auto response = [&](int radial, double tolerance) {
    TransientOptions o = current_step(0.3);
    o.value = 4.0;  // H0 = N I / length = 20 kA/m
    o.tolerance = tolerance;
    return simulate(c, c.problem(bh), c.mesh(radial), o).result;
  };
  const auto coarse = response(24, 1e-4), fine = response(48, 1e-6);
  ASSERT_TRUE(coarse.t63 && coarse.t90 && fine.t63 && fine.t90);
  std::cout << "t63 " << *coarse.t63 << " / " << *fine.t63 << ", t90 " << *coarse.t90 << " / "
            << *fine.t90 << ", energy balance " << coarse.energy.max_step_error
            << ", numerical dissipation " << coarse.energy.max_step_dissipation << " (worst step), "
            << coarse.energy.numerical_dissipation / coarse.energy.source << " (run)\n";
  EXPECT_NEAR(*coarse.t63 / *fine.t63, 1.0, 0.01);
  EXPECT_NEAR(*coarse.t90 / *fine.t90, 1.0, 0.01);
  // Energy balance with a B-H curve: the scheme's identity source = field work + losses holds
  // per step to the Newton tolerance (the 1e-6); field work - dW is the 2-point rule's
  // error in s, reported as numerical dissipation (measured below).
  EXPECT_LT(coarse.energy.max_step_error, 1e-6);
  EXPECT_LT(coarse.energy.total_error, 1e-6);
  EXPECT_LT(fine.energy.max_step_error, 1e-6);
  // Saturation makes it faster than the linear tau-based estimate at mu_r(0).
  EXPECT_LT(*fine.t63, 0.5);
}

}  // namespace

namespace {

// The midpoint scheme's numerical dissipation on a B-H curve (field work - dW, the 2-point
// Gauss rule's error in s where the B-H curve's knee is crossed within a step) must vanish with
// the step: |sum over the run| of a saturating voltage step (0.3 V, 0.2 Ohm, 20 ms) at N = 50,
// 100, 200, 400 equal steps decreasing at an observed order >= 2 over the range (measured 3.0,
// docs/transient.md); the identity source = field work + losses holds per step to 1e-6.
TEST(TransientCylinder, SaturatingNumericalDissipationVanishesWithTheStep) {
  const test::Cylinder c;
  const auto problem = c.problem(test::kSaturatingBh);
  const auto mesh = c.mesh(12);
  std::vector<double> dissipation;
  for (int steps : {50, 100, 200, 400}) {
    TransientOptions o = voltage_step(0.02);
    o.value = 0.3;  // 1.5 A final: H0 = 7.5 kA/m, B ~ 1.8 T past the knee at the surface
    o.steps = steps;
    const auto e = simulate(c, problem, mesh, o).result.energy;
    EXPECT_LT(e.max_step_error, 1e-6) << steps;
    dissipation.push_back(std::abs(e.numerical_dissipation) /
                          std::max(std::abs(e.source), e.eddy_loss));
  }
  std::cout << "relative numerical dissipation " << dissipation[0] << " " << dissipation[1] << " "
            << dissipation[2] << " " << dissipation[3] << "\n";
  const double order = std::log2(dissipation[0] / dissipation[3]) / 3.0;
  std::cout << "observed order " << order << "\n";
  EXPECT_GT(dissipation[0], 1e-9);  // visible at the coarsest step
  EXPECT_GT(order, 2.0);
}

}  // namespace
