// Incremental inductance, current sweep and energies of a nonlinear iron circuit.

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "core/error.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"
#include "tests/magnetostatics/pot_core.hpp"
#include "tests/magnetostatics/steel.hpp"

namespace rheomag::magnetostatics {
namespace {

SolveOptions tight() {
  SolveOptions options;
  options.newton.relative_tolerance = 1e-11;
  return options;
}

TEST(Incremental, ExactIncrementalInductanceEqualsFiniteDifference) {
  // Reference: central difference (lambda(I + h) - lambda(I - h)) / 2h, h = 1e-3 A, at I = 3 A
  // (iron partly saturated, so dlambda/dI differs from lambda/I). Truncation O(h^2) ~ 1e-6,
  // Newton tolerance 1e-11: tolerance 1e-4 relative.
  const test::PotCore core;
  MagnetostaticSolver solver(test::pot_core_problem(test::aisi1010(), 400, 3.0, 2),
                             test::pot_core_mesh(core, 1.0, 2), tight());
  const double current = 3.0, h = 1e-3;
  const Solution s = solver.solve({current});
  const double plus = solver.solve({current + h}).flux_linkage[0];
  const double minus = solver.solve({current - h}).flux_linkage[0];
  const double fd = (plus - minus) / (2 * h);
  const double secant = s.flux_linkage[0] / current;
  std::printf("L_inc %.6e H, FD %.6e H, secant %.6e H\n", s.incremental_inductance[0], fd, secant);
  EXPECT_NEAR(s.incremental_inductance[0], fd, 1e-4 * fd);
  EXPECT_LT(s.incremental_inductance[0], 0.9 * secant);  // saturation: L_inc < L_secant
}

TEST(Incremental, EachNewtonIterateIsAssembledOnceAndItsTangentGivesTheInductance) {
  // In a warm-started incremental solve Newton's residual at each iterate also assembles the
  // tangent there, which the Jacobian at that iterate and the final dlambda/dI take as they are.
  // Counted (local corrections off: they move an iterate after its residual): one per iterate
  // (the start and each full step), nothing more. A cold solve keeps a residual per step and a
  // residual-and-tangent per Jacobian. The residual at A = 0 (Newton's scale, a cold solve's
  // start) depends on no current: the solver's first solve assembles it, and every later solve
  // takes it as it is, giving bitwise the same solution.
  // Reference for the tangent so reused: dlambda/dI = f^T K(A)^{-1} f from the solver's public
  // tangent at the solution (f: the source per ampere, R(A, 0) - R(A, 1 A)), by a separate
  // sparse LDL^T: tolerance 1e-9 relative (two direct solves of the same matrix).
  const test::PotCore core;
  SolveOptions options = tight();
  options.newton.local_iterations = 0;
  MagnetostaticSolver solver(test::pot_core_problem(test::aisi1010(), 400, 3.0, 2),
                             test::pot_core_mesh(core, 1.0, 2), options);
  int before = solver.assemblies();
  const Solution first = solver.solve({2.9});
  const int first_assemblies = solver.assemblies() - before;
  before = solver.assemblies();
  const Solution near = solver.solve({2.9});
  EXPECT_EQ(solver.assemblies() - before, first_assemblies - 1);
  EXPECT_EQ(near.a, first.a);
  before = solver.assemblies();
  const Solution s = solver.solve_incremental({3.0}, &near.a);
  ASSERT_GE(s.newton.iterations, 2);
  for (double alpha : s.newton.step_lengths) ASSERT_EQ(alpha, 1.0);
  EXPECT_EQ(solver.assemblies() - before, s.newton.iterations + 1);
  before = solver.assemblies();
  const Solution cold = solver.solve_incremental({3.0});
  const int k = cold.newton.iterations;
  ASSERT_GE(k, 2);
  for (double alpha : cold.newton.step_lengths) ASSERT_EQ(alpha, 1.0);
  EXPECT_EQ(solver.assemblies() - before, k + k + 1);
  const Eigen::VectorXd f = solver.residual(s.a, {0.0}) - solver.residual(s.a, {1.0});
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt(solver.tangent(s.a));
  ASSERT_EQ(ldlt.info(), Eigen::Success);
  const double reference = f.dot(ldlt.solve(f));
  EXPECT_NEAR(s.incremental_inductance[0], reference, 1e-9 * reference);
}

TEST(Incremental, AWarmStartedIncrementalSolveTakesNoLocalCorrections) {
  // A warm-started solve_incremental (the quasi-static table's solves, an optimiser's
  // neighbours) skips the local corrections a plain solve makes: from a nearby state they rarely
  // pay and would waste the tangent its residual assembles. A plain solve from the same start
  // takes local steps here, so the skip is what the counts show: no local step, and one assembly
  // per residual the line searches tried plus the start. Reference for the solution: the plain
  // solve's, within Newton's tolerance (|R| / |R(0)| < 1e-11 for both: fields within 1e-9 of the
  // largest |A|).
  const test::PotCore core;
  MagnetostaticSolver solver(test::pot_core_problem(test::aisi1010(), 400, 3.0, 2),
                             test::pot_core_mesh(core, 1.0, 2), tight());
  const Solution low = solver.solve({1.0});
  const Solution plain = solver.solve({3.0}, &low.a);
  ASSERT_GT(plain.newton.local_steps, 0)
      << "this start needs no local step: the test shows nothing";
  const int before = solver.assemblies();
  const Solution warm = solver.solve_incremental({3.0}, &low.a);
  EXPECT_EQ(warm.newton.local_steps, 0);
  int trials = 0;  // residuals the line searches assembled: one per step length tried
  for (double alpha : warm.newton.step_lengths) trials += 1 + std::lround(-std::log2(alpha));
  EXPECT_EQ(solver.assemblies() - before, trials + 1);
  const double difference =
      (warm.a - plain.a).cwiseAbs().maxCoeff() / plain.a.cwiseAbs().maxCoeff();
  std::printf("Newton steps: plain %d (%d local), warm incremental %d; field difference %.2e\n",
              plain.newton.iterations, plain.newton.local_steps, warm.newton.iterations,
              difference);
  EXPECT_LT(difference, 1e-9);
}

TEST(Incremental, AFrozenFactorSolvesWithTheTangentAtTheSolutionAfterTheSolverMovedOn) {
  // freeze_tangent_factor() copies the factorisation of the tangent at an incremental solve's
  // solution (the one behind dlambda/dI). Reference: that tangent, assembled again at the
  // solution: K x = b to 1e-10 relative, also after the solver has factorised other tangents,
  // and x = dA/dI for b = F. Solution::residual is R(A) at the solution: the residual assembled
  // there, to 1e-12 of |R(0)|, and within Newton's tolerance.
  const test::PotCore core;
  MagnetostaticSolver solver(test::pot_core_problem(test::aisi1010(), 400, 3.0, 2),
                             test::pot_core_mesh(core, 1.0, 2), tight());
  const Solution low = solver.solve({1.0});
  const Solution s = solver.solve_incremental({3.0}, &low.a);
  const std::shared_ptr<const FrozenFactor> frozen = solver.freeze_tangent_factor();
  ASSERT_TRUE(frozen);
  ASSERT_EQ(frozen->size(), solver.dofs().free_count());
  EXPECT_GT(frozen->bytes(), 0u);
  solver.solve_incremental({0.5}, &low.a);  // the solver's own factor moves on
  const SparseMatrix k = solver.tangent(s.a);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(frozen->size(), 1.0, 2.0);
  const Eigen::VectorXd x = frozen->solve(b);
  EXPECT_LT((k.selfadjointView<Eigen::Lower>() * x - b).norm(), 1e-10 * b.norm());
  const Eigen::VectorXd f = solver.nodes_to_free(solver.circuit_source(0));
  EXPECT_LT((frozen->solve(f) - s.incremental_field.at(0)).norm(),
            1e-8 * s.incremental_field.at(0).norm());
  const Eigen::VectorXd r = solver.residual(s.a, {3.0});
  const double scale = solver.residual(Eigen::VectorXd::Zero(s.a.size()), {3.0}).norm();
  ASSERT_EQ(s.residual.size(), r.size());
  EXPECT_LT((s.residual - r).norm(), 1e-12 * scale);
  EXPECT_LE(s.residual.norm(), tight().newton.relative_tolerance * scale);
  EXPECT_THROW(frozen->solve(Eigen::VectorXd::Ones(3)), ConvergenceError);
}

TEST(Incremental, FactorisedIncrementalTangentIsTheOneFrozenWithoutCgIterations) {
  // factorise_incremental_tangent(true): dA/dI is solved with a factorisation of the tangent at
  // the solution, so freeze_tangent_factor() then copies it without factorising again, and no
  // CG iteration is spent on dA/dI. Reference: the same warm-started solve with the default (CG
  // preconditioned with Newton's last factorisation, to 1e-12 of F.x): dlambda/dI within 1e-10
  // relative, dA/dI within 1e-8 of its norm (CG stops on the functional F.x; measured 3.7e-9),
  // the fields identical (the same Newton path: the setting acts after it).
  const test::PotCore core;
  auto incremental = [&](bool factorise, int& cg, int& factorised_by_freeze) {
    MagnetostaticSolver solver(test::pot_core_problem(test::aisi1010(), 400, 3.0, 2),
                               test::pot_core_mesh(core, 1.0, 2), tight());
    const Solution low = solver.solve({2.9});
    solver.factorise_incremental_tangent(factorise);  // after it: the same Newton path below
    const int cg_before = solver.reuse_iterations();
    Solution s = solver.solve_incremental({3.0}, &low.a);
    const int before = solver.factorizations();
    EXPECT_TRUE(solver.freeze_tangent_factor());
    factorised_by_freeze = solver.factorizations() - before;
    cg = solver.reuse_iterations() - cg_before;
    return s;
  };
  int cg_default = 0, cg_factorised = 0, freeze_default = 0, freeze_factorised = 0;
  const Solution by_cg = incremental(false, cg_default, freeze_default);
  const Solution factorised = incremental(true, cg_factorised, freeze_factorised);
  std::printf("CG iterations: default %d, factorised %d; factorisations by the freeze: %d, %d\n",
              cg_default, cg_factorised, freeze_default, freeze_factorised);
  ASSERT_EQ(freeze_default, 1) << "this solve's dA/dI was not found by CG: the test shows nothing";
  EXPECT_EQ(freeze_factorised, 0);
  EXPECT_LT(cg_factorised, cg_default);
  EXPECT_EQ(factorised.a, by_cg.a);
  EXPECT_NEAR(factorised.incremental_inductance.at(0) / by_cg.incremental_inductance.at(0), 1.0,
              1e-10);
  EXPECT_LT((factorised.incremental_field.at(0) - by_cg.incremental_field.at(0)).norm(),
            1e-8 * by_cg.incremental_field.at(0).norm());
}

TEST(Incremental, SweepCoenergyIsTheIntegralOfFluxLinkage) {
  // Reference: W'(I) = integral_0^I lambda(i) di (co-energy theorem, exact for the discrete
  // problem too); lambda(I) from a 21-point sweep 0..4 A integrated by Simpson's rule:
  // tolerance 2e-3 relative. Also W + W' = lambda I (= integral B.H dV), tolerance 1e-7, and the
  // sweep's incremental inductance at I = 0 equals its linear secant limit.
  const test::PotCore core;
  MagnetostaticSolver solver(test::pot_core_problem(test::aisi1010(), 400, 0.0, 2),
                             test::pot_core_mesh(core, 1.0, 2), tight());
  std::vector<double> currents;
  for (int k = 0; k <= 20; ++k) currents.push_back(0.2 * k);
  const int before = solver.factorizations();
  const auto table = solver.sweep(0, currents);
  ASSERT_EQ(table.size(), currents.size());
  std::printf("sweep: %d factorisations (one symbolic analysis), iterations:",
              solver.factorizations() - before);
  for (const auto& row : table) std::printf(" %d", row.newton_iterations);
  std::printf("\n");
  double simpson = 0.0;
  for (std::size_t k = 0; k < table.size(); ++k) {
    const double w = (k == 0 || k + 1 == table.size()) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    simpson += w * table[k].flux_linkage;
  }
  simpson *= 0.2 / 3.0;
  const Solution end = solver.solve({4.0});
  const Results res = compute_results(solver, end);
  std::printf("co-energy %.6e J, integral lambda dI %.6e J, energy %.6e J\n", res.coenergy, simpson,
              res.energy);
  EXPECT_NEAR(res.coenergy, simpson, 2e-3 * simpson);
  EXPECT_NEAR(res.energy + res.coenergy, end.flux_linkage[0] * 4.0, 1e-7 * res.coenergy);
  EXPECT_GT(res.coenergy, res.energy);  // saturating iron: W' > W
  EXPECT_EQ(table[0].flux_linkage, 0.0);
  EXPECT_EQ(table[0].secant_inductance, table[0].incremental_inductance);
  EXPECT_GT(table[1].secant_inductance, table[20].secant_inductance);
}

TEST(Incremental, LinearEnergyIsHalfLISquared) {
  // Reference: for linear materials W = W' = L I^2 / 2 and L_inc = L (discrete identities,
  // tolerance 1e-9 relative); the linear factorisation is reused by a second solve.
  const test::PotCore core;
  MagnetostaticSolver solver(
      test::pot_core_problem({"iron", 1000.0, {}, 0.0, "linear"}, 400, 2.0, 2),
      test::pot_core_mesh(core, 1.0, 2));
  const Solution s = solver.solve();
  const Results res = compute_results(solver, s);
  const double l = res.circuits.at(0).inductance;
  EXPECT_NEAR(res.energy, 0.5 * l * 4.0, 1e-9 * res.energy);
  EXPECT_NEAR(res.coenergy, res.energy, 1e-9 * res.energy);
  EXPECT_NEAR(res.circuits[0].incremental_inductance, l, 1e-9 * l);
  const int factorizations = solver.factorizations();
  const Solution again = solver.solve({5.0});
  EXPECT_EQ(solver.factorizations(), factorizations);
  EXPECT_NEAR(again.flux_linkage[0], 2.5 * s.flux_linkage[0], 1e-9 * again.flux_linkage[0]);
}

}  // namespace
}  // namespace rheomag::magnetostatics
