// Heat conduction against closed forms (any heat-transfer text, e.g. Incropera & DeWitt,
// "Fundamentals of Heat and Mass Transfer", ch. 3.5 and 5.3): a long cylinder with uniform heat
// generation, a composite cylinder with a convective rim, a lumped body's exponential cooling,
// and the energy balance of every solution.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "tests/thermal/heat_geometry.hpp"
#include "thermal/heat_solver.hpp"

namespace rheomag::thermal {
namespace {

using test::Ring;

/// Largest nodal temperature on the axis (r = 0) of a solution.
double axis_temperature(const mesh::Mesh& mesh, const HeatSolution& s) {
  double t = -1e300;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    if (mesh.nodes[i].r < 1e-12) t = std::max(t, s.temperature[static_cast<Eigen::Index>(i)]);
  return t;
}

// Long cylinder, radius R, uniform q, insulated ends (so it is the infinite cylinder), rim
// convection h to T_amb: T(0) = T_amb + q R / (2 h) + q R^2 / (4 k). T is quadratic in r, so P2
// reproduces it to rounding; P1 converges at second order at the nodes.
TEST(ClosedForm, CylinderWithUniformGenerationCentreTemperature) {
  const double radius = 0.01, k = 15.0, q = 2e6, h = 50.0, ambient = 20.0;
  const std::vector<Ring> rings{{0.0, radius, k, 3e6, q}};
  const cases::Problem problem = test::rings_problem(rings, 0.004);
  const double expected = ambient + q * radius / (2.0 * h) + q * radius * radius / (4.0 * k);
  const double rise = expected - ambient;
  {
    const mesh::Mesh mesh = test::mesh_of(problem, radius / 8.0, 2);
    HeatSolver solver(problem, mesh,
                      test::rings_model(rings, {"rim", SurfaceKind::convection, h, ambient}));
    const HeatSolution s = solver.steady();
    EXPECT_NEAR(axis_temperature(mesh, s), expected, 1e-7 * rise);  // P2: exact to rounding
    EXPECT_NEAR(s.balance_error(), 0.0, 1e-8);
  }
  double previous_error = 0.0;
  for (int refine : {4, 8}) {  // P1: error at least 3x smaller per halving (second order)
    const mesh::Mesh mesh = test::mesh_of(problem, radius / refine, 1);
    HeatSolver solver(problem, mesh,
                      test::rings_model(rings, {"rim", SurfaceKind::convection, h, ambient}));
    const double error = std::abs(axis_temperature(mesh, solver.steady()) - expected);
    EXPECT_LT(error, 0.01 * rise);
    if (previous_error > 0.0) {
      EXPECT_LT(error, previous_error / 3.0);
    }
    previous_error = error;
  }
}

// Composite cylinder: a heated core (radius a, k1, q) in a shell (a..b, k2, no source) with rim
// convection: T(0) = T_amb + q a^2 / (2 b h) + q a^2 ln(b / a) / (2 k2) + q a^2 / (4 k1).
TEST(ClosedForm, CompositeCylinderWithConvectiveRim) {
  const double a = 0.008, b = 0.02, k1 = 0.8, k2 = 50.0, q = 5e5, h = 20.0, ambient = 25.0;
  const std::vector<Ring> rings{{0.0, a, k1, 2e6, q}, {a, b, k2, 3.5e6, 0.0}};
  const cases::Problem problem = test::rings_problem(rings, 0.005);
  const mesh::Mesh mesh = test::mesh_of(problem, 0.0008, 2);
  HeatSolver solver(problem, mesh,
                    test::rings_model(rings, {"rim", SurfaceKind::convection, h, ambient}));
  const HeatSolution s = solver.steady();
  const double expected = ambient + q * a * a / (2.0 * b * h) +
                          q * a * a * std::log(b / a) / (2.0 * k2) + q * a * a / (4.0 * k1);
  EXPECT_NEAR(axis_temperature(mesh, s), expected, 1e-5 * (expected - ambient));
  // The rim's heat flow is everything the core makes: q pi a^2 height.
  EXPECT_NEAR(s.surface_heat_flow[0], q * std::numbers::pi * a * a * 0.005, 1e-8 * s.source_power);
  EXPECT_NEAR(s.balance_error(), 0.0, 1e-8);
}

// A fixed rim temperature: T(0) = T_rim + q R^2 / (4 k); the heat leaves through the fixed rim
// (the reaction of its rows).
TEST(ClosedForm, FixedRimTemperatureAndItsHeatFlow) {
  const double radius = 0.012, k = 2.0, q = 1e5, rim = 60.0, height = 0.003;
  const std::vector<Ring> rings{{0.0, radius, k, 3e6, q}};
  const cases::Problem problem = test::rings_problem(rings, height);
  const mesh::Mesh mesh = test::mesh_of(problem, radius / 6.0, 2);
  SurfaceCondition fixed{"rim", SurfaceKind::fixed_temperature};
  fixed.temperature = rim;
  HeatSolver solver(problem, mesh, test::rings_model(rings, fixed));
  const HeatSolution s = solver.steady();
  EXPECT_NEAR(axis_temperature(mesh, s), rim + q * radius * radius / (4.0 * k), 1e-7 * 2.0);
  EXPECT_NEAR(s.surface_heat_flow[0], q * std::numbers::pi * radius * radius * height,
              1e-8 * s.source_power);
}

// Lumped body: a conductive cylinder (Biot = h (V/A) / k = 2e-5) cooled on every face:
// T(t) = T_amb + (T0 - T_amb) exp(-t / tau), tau = rho c V / (h A). BDF2 with dt = tau / 100.
TEST(ClosedForm, LumpedBodyTransientIsExponential) {
  const double radius = 0.01, height = 0.02, k = 400.0, c = 3.4e6, h = 15.0;
  const double ambient = 20.0, start = 80.0;
  const std::vector<Ring> rings{{0.0, radius, k, c, 0.0}};
  const cases::Problem problem = test::rings_problem(rings, height);
  const mesh::Mesh mesh = test::mesh_of(problem, radius / 4.0, 2);
  HeatModel model = test::rings_model(rings, {"rim", SurfaceKind::convection, h, ambient});
  model.surface_of_boundary = {0, 0};  // the ends convect too
  HeatSolver solver(problem, mesh, model);
  const double volume = std::numbers::pi * radius * radius * height;
  const double area =
      2.0 * std::numbers::pi * radius * height + 2.0 * std::numbers::pi * radius * radius;
  const double tau = c * volume / (h * area);
  double worst = 0.0, worst_balance = 0.0;
  solver.transient(solver.uniform(start), tau / 100.0, 300, [&](const HeatSolution& s) {
    const double exact = ambient + (start - ambient) * std::exp(-s.time / tau);
    worst = std::max(worst, std::abs(s.regions[0].mean - exact));
    if (s.time > 0.0)
      worst_balance = std::max(worst_balance, std::abs(s.storage_power + s.surface_heat_flow[0]) /
                                                  std::abs(s.surface_heat_flow[0]));
    return true;
  });
  EXPECT_LT(worst, 1e-3 * (start - ambient));  // BDF2 at tau/100, Biot 2e-5
  EXPECT_LT(worst_balance, 1e-8);              // stored + convected = 0 without sources, every step
}

// Heating from ambient under a source: the mean rises as the lumped body's 1 - exp(-t/tau) and
// ends at the steady solution.
TEST(ClosedForm, TransientReachesTheSteadySolution) {
  const double radius = 0.01, height = 0.01, k = 200.0, c = 2.4e6, h = 30.0, q = 4e4;
  const std::vector<Ring> rings{{0.0, radius, k, c, q}};
  const cases::Problem problem = test::rings_problem(rings, height);
  const mesh::Mesh mesh = test::mesh_of(problem, radius / 4.0, 2);
  HeatModel model = test::rings_model(rings, {"rim", SurfaceKind::convection, h, 20.0});
  model.surface_of_boundary = {0, 0};
  HeatSolver solver(problem, mesh, model);
  const HeatSolution steady = solver.steady();
  const double area = 2.0 * std::numbers::pi * radius * (height + radius);
  const double tau = c * std::numbers::pi * radius * radius * height / (h * area);
  const HeatSolution last = solver.transient(solver.uniform(20.0), tau / 50.0, 1000,
                                             [](const HeatSolution&) { return true; });
  EXPECT_NEAR(last.regions[0].mean, steady.regions[0].mean,
              1e-6 * (steady.regions[0].mean - 20.0));  // 20 tau: exp(-20) = 2e-9
  EXPECT_NEAR(last.balance_error(), 0.0, 1e-8);
}

// A through-flow exchange beta (T - T_in) balancing a uniform source with the surfaces
// insulated: T = T_in + q / beta everywhere, and the flow carries all the heat.
TEST(ClosedForm, ThroughFlowExchangeCarriesTheSource) {
  const double q = 3e5, beta = 2e4, inlet = 35.0;
  std::vector<Ring> rings{{0.0, 0.004, 0.6, 2.4e6, q}, {0.004, 0.01, 50.0, 3.5e6, 0.0}};
  const cases::Problem problem = test::rings_problem(rings, 0.006);
  const mesh::Mesh mesh = test::mesh_of(problem, 0.001, 2);
  HeatModel model = test::rings_model(rings, {"rim", SurfaceKind::insulated});
  for (HeatRegion& region : model.regions) {
    region.exchange = beta;
    region.exchange_temperature = inlet;
  }
  model.regions[1].source = 0.0;
  HeatSolver solver(problem, mesh, model);
  const HeatSolution s = solver.steady();
  // Only ring 0 is heated, so T is not uniform; but the exchange removes everything made.
  EXPECT_NEAR(s.exchange_heat_flow, s.source_power, 1e-8 * s.source_power);
  EXPECT_NEAR(s.balance_error(), 0.0, 1e-8);
  // Uniform source in both rings: T = T_in + q / beta exactly.
  solver.set_sources({q, q});
  const HeatSolution uniform = solver.steady();
  EXPECT_NEAR(uniform.regions[0].mean, inlet + q / beta, 1e-9 * q / beta);
  EXPECT_NEAR(uniform.regions[1].max, inlet + q / beta, 1e-9 * q / beta);
}

TEST(HeatSolverInput, RefusesBadModels) {
  const std::vector<Ring> rings{{0.0, 0.01, 1.0, 1e6, 0.0}};
  const cases::Problem problem = test::rings_problem(rings, 0.01);
  const mesh::Mesh mesh = test::mesh_of(problem, 0.003, 1);
  HeatModel negative = test::rings_model(rings, {"rim", SurfaceKind::convection, 10.0, 20.0});
  negative.regions[0].conductivity = -1.0;
  EXPECT_THROW(HeatSolver(problem, mesh, negative), InputError);
  HeatModel insulated = test::rings_model(rings, {"rim", SurfaceKind::insulated});
  EXPECT_THROW(HeatSolver(problem, mesh, insulated), InputError);
}

}  // namespace
}  // namespace rheomag::thermal
