// The pieces of Newton's energy line search and local corrections: the energy's gradient is the
// residual, a patch's residual rows, tangent block and energy changes agree with the global ones,
// and the corrections change the number of Newton steps but not the solution.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <random>

#include "magnetostatics/solver.hpp"
#include "tests/magnetostatics/pot_core.hpp"
#include "tests/magnetostatics/steel.hpp"

namespace rheomag::magnetostatics {
namespace {

/// Pot core at 2 A, P2, 2 cells/mm; with a mixed (Robin) outer boundary when `robin`, so that
/// the boundary terms are checked too (c0 = 1/(mu0 R) with R = 20 mm, c1 = 1e-3).
MagnetostaticSolver pot_core_solver(bool robin, SolveOptions options = {}) {
  cases::Problem problem = test::pot_core_problem(test::aisi1010(), 400, 2.0, 2);
  if (robin) {
    problem.boundaries = {
        {"outside, mixed", cases::BoundaryKind::mixed, 0.0, 1.0 / (4e-7 * M_PI * 0.02), 1e-3}};
  }
  const test::PotCore core;
  return MagnetostaticSolver(problem, test::pot_core_mesh(core, 2.0, 2), options);
}

/// The solution perturbed by up to 20 % per free node (partly saturated, not an equilibrium).
Eigen::VectorXd perturbed_field(MagnetostaticSolver& solver) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd a = solver.solve().a;
  for (int node : solver.dofs().node_of_dof) a[node] *= 1.0 + 0.2 * uniform(random);
  return a;
}

TEST(LocalCorrection, EnergyGradientIsTheResidual) {
  // Reference: central difference (E(A + e d) - E(A - e d)) / 2e with e = 1e-6 |A| / |d|
  // (truncation O(e^2)), against R(A) . d from the assembly without sources; tolerance 1e-7 of
  // |R| |d| (R . d itself has cancellations). With and without the Robin boundary terms.
  for (bool robin : {false, true}) {
    MagnetostaticSolver solver = pot_core_solver(robin);
    const Eigen::VectorXd a = perturbed_field(solver);
    const DofMap& dofs = solver.dofs();
    std::mt19937 random(11);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::VectorXd direction = Eigen::VectorXd::Zero(a.size());
    Eigen::VectorXd d_free(dofs.free_count());
    for (int d = 0; d < dofs.free_count(); ++d) {
      d_free[d] = direction[dofs.node_of_dof[d]] = uniform(random);
    }
    const double eps = 1e-6 * a.norm() / direction.norm();
    const Assembler& assembler = solver.assembler();
    const double fd =
        (assembler.energy(a + eps * direction) - assembler.energy(a - eps * direction)) / (2 * eps);
    Eigen::VectorXd r;
    assembler.assemble(a, r, nullptr);
    const double exact = r.dot(d_free);
    std::printf("robin %d: dE/de %.9e, R.d %.9e, |R| |d| %.3e\n", robin, fd, exact,
                r.norm() * d_free.norm());
    EXPECT_NEAR(fd, exact, 1e-7 * r.norm() * d_free.norm());
  }
}

TEST(LocalCorrection, PatchAgreesWithTheGlobalAssembly) {
  // Reference: the global residual, tangent and energy at the same field. A patch's rows must
  // be complete (every triangle and edge touching its dofs): residual rows and tangent entries to
  // 1e-12 of their largest value (different order of the same additions); the energy change of a
  // move of the patch dofs equals the global change to 1e-8 relative (the global total is
  // ~1e3 x larger, its rounding sets the tolerance). Patch seeded at the dof of largest |R|, plus
  // a boundary dof so that Robin edges are included.
  MagnetostaticSolver solver = pot_core_solver(true);
  const Assembler& assembler = solver.assembler();
  const DofMap& dofs = solver.dofs();
  const Eigen::VectorXd a = perturbed_field(solver);
  Eigen::VectorXd r;
  SparseMatrix k = assembler.pattern();
  assembler.assemble(a, r, &k);
  int worst = 0;
  r.cwiseAbs().maxCoeff(&worst);
  int boundary_dof = -1;
  for (const mesh::BoundaryEdge& edge : solver.mesh().boundary_edges) {
    if (edge.boundary >= 0 && dofs.dof_of_node[edge.nodes[0]] >= 0) {
      boundary_dof = dofs.dof_of_node[edge.nodes[0]];
      break;
    }
  }
  ASSERT_GE(boundary_dof, 0);
  const Patch patch = assembler.patch({worst, boundary_dof}, 2);
  ASSERT_FALSE(patch.edges.empty());
  Eigen::VectorXd rows;
  SparseMatrix block;
  assembler.assemble_patch(patch, a, rows, &block);
  const int unknowns = static_cast<int>(patch.dofs.size());
  double row_error = 0.0;
  for (int i = 0; i < unknowns; ++i)
    row_error = std::max(row_error, std::abs(rows[i] - r[patch.dofs[i]]));
  EXPECT_LT(row_error, 1e-12 * r.cwiseAbs().maxCoeff());
  const Eigen::MatrixXd dense_block = Eigen::MatrixXd(block);
  const Eigen::MatrixXd dense_global = Eigen::MatrixXd(k);  // lower triangle
  double matrix_error = 0.0, matrix_max = 0.0;
  for (int i = 0; i < unknowns; ++i) {
    for (int j = 0; j <= i; ++j) {
      const double global = dense_global(patch.dofs[i], patch.dofs[j]);
      matrix_error = std::max(matrix_error, std::abs(dense_block(i, j) - global));
      matrix_max = std::max(matrix_max, std::abs(global));
    }
  }
  EXPECT_LT(matrix_error, 1e-12 * matrix_max);

  Eigen::VectorXd moved = a;
  for (int d : patch.dofs) moved[dofs.node_of_dof[d]] *= 1.3;
  const double global_change = assembler.energy(moved) - assembler.energy(a);
  const double patch_change =
      assembler.patch_energy(patch, moved) - assembler.patch_energy(patch, a);
  std::printf("patch of %d dofs, %zu triangles, %zu edges: energy change %.9e (global %.9e)\n",
              unknowns, patch.elements.size(), patch.edges.size(), patch_change, global_change);
  EXPECT_NEAR(patch_change, global_change, 1e-8 * std::abs(global_change));
}

TEST(LocalCorrection, FewerNewtonStepsSameSolution) {
  // Reference: the same solve without local corrections (local_iterations = 0); both converge to
  // a relative residual of 1e-8, so lambda and dlambda/dI agree to 1e-7 relative. The pot core at
  // 2 A saturates at the re-entrant corners of the window: the corrections must act there
  // (local steps > 0) and save global Newton steps.
  SolveOptions without;
  without.newton.local_iterations = 0;
  MagnetostaticSolver plain = pot_core_solver(false, without);
  MagnetostaticSolver corrected = pot_core_solver(false);
  const Solution p = plain.solve();
  const Solution c = corrected.solve();
  std::printf("Newton steps %d without, %d with %d local steps\n", p.newton.iterations,
              c.newton.iterations, c.newton.local_steps);
  EXPECT_EQ(p.newton.local_steps, 0);
  EXPECT_GT(c.newton.local_steps, 0);
  EXPECT_LT(c.newton.iterations, p.newton.iterations);
  EXPECT_NEAR(c.flux_linkage[0], p.flux_linkage[0], 1e-7 * p.flux_linkage[0]);
  EXPECT_NEAR(c.incremental_inductance[0], p.incremental_inductance[0],
              1e-7 * p.incremental_inductance[0]);
}

}  // namespace
}  // namespace rheomag::magnetostatics
