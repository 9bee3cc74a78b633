// The Newton tangent is the exact derivative of the residual: finite-difference check.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <random>
#include <string>

#include "magnetostatics/solver.hpp"
#include "tests/magnetostatics/pot_core.hpp"
#include "tests/magnetostatics/steel.hpp"

namespace rheomag::magnetostatics {
namespace {

void check_tangent(int order, double current) {
  // Reference: central difference (R(A + e d) - R(A - e d)) / 2e, e = 1e-6 |A|/|d|, whose
  // truncation error is O(e^2); tolerance 1e-6 relative to |K d| (a wrong rank-one term or a
  // missing Robin/axis contribution gives O(1) differences).
  const test::PotCore core;
  SolveOptions options;
  options.incremental_inductance = false;
  MagnetostaticSolver solver(test::pot_core_problem(test::aisi1010(), 400, current, order),
                             test::pot_core_mesh(core, 0.7, order), options);
  const Solution s = solver.solve();
  // Evaluate away from the solution, where the iron is partly saturated.
  std::mt19937 random(42);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd a = s.a;
  const DofMap& dofs = solver.dofs();
  Eigen::VectorXd direction = Eigen::VectorXd::Zero(a.size());
  for (int d = 0; d < dofs.free_count(); ++d) {
    a[dofs.node_of_dof[d]] *= 1.0 + 0.2 * uniform(random);
    direction[dofs.node_of_dof[d]] = uniform(random);
  }
  const double eps = 1e-6 * a.norm() / direction.norm();
  const Eigen::VectorXd fd = (solver.residual(a + eps * direction, s.currents) -
                              solver.residual(a - eps * direction, s.currents)) /
                             (2 * eps);
  const SparseMatrix k = solver.tangent(a);
  Eigen::VectorXd d_free(dofs.free_count());
  for (int d = 0; d < dofs.free_count(); ++d) d_free[d] = direction[dofs.node_of_dof[d]];
  const Eigen::VectorXd kd = k.selfadjointView<Eigen::Lower>() * d_free;
  const double error = (kd - fd).norm() / kd.norm();
  std::printf("P%d, I = %.1f A: |K d - FD| / |K d| = %.2e\n", order, current, error);
  EXPECT_LT(error, 1e-6);
}

TEST(Jacobian, MatchesFiniteDifferencesP1) {
  check_tangent(1, 2.0);
}
TEST(Jacobian, MatchesFiniteDifferencesP2) {
  check_tangent(2, 2.0);
}
TEST(Jacobian, MatchesFiniteDifferencesP2Saturated) {
  check_tangent(2, 6.0);
}

}  // namespace
}  // namespace rheomag::magnetostatics
