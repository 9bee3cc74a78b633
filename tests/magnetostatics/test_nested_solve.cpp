// Nested iteration: the interpolation between meshes of one geometry reproduces the fields its
// elements hold, and a fine solve started from coarse solutions (with or without frozen tangents)
// gives the fine solver's own lambda and dlambda/dI.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <vector>

#include "magnetostatics/nested_solve.hpp"
#include "magnetostatics/prolongation.hpp"
#include "magnetostatics/solver.hpp"
#include "tests/magnetostatics/pot_core.hpp"
#include "tests/magnetostatics/steel.hpp"

namespace rheomag::magnetostatics {
namespace {

/// A quadratic in (r, z) [m], of order 1 when `order` is 1.
double polynomial(const mesh::Point& p, int order) {
  const double r = 1e3 * p.r, z = 1e3 * p.z;  // mm, values of order 1..1e3
  const double linear = 1.0 + 2.0 * r - 3.0 * z;
  return order == 1 ? linear : linear + 0.4 * r * r - 0.5 * r * z + 0.6 * z * z;
}

TEST(Prolongation, ReproducesTheElementsPolynomials) {
  // Reference: the polynomial itself at the target nodes; P1 and P2 reproduce linear and
  // quadratic fields exactly, so the only error is rounding (tolerance 1e-12 of the largest
  // value). The meshes are not nested (1 and 2.3 cells/mm), so nodes fall anywhere in the
  // coarse triangles.
  const test::PotCore core;
  for (int order : {1, 2}) {
    const mesh::Mesh from = test::pot_core_mesh(core, 1.0, order);
    const mesh::Mesh to = test::pot_core_mesh(core, 2.3, order);
    Eigen::VectorXd values(static_cast<Eigen::Index>(from.nodes.size()));
    for (std::size_t i = 0; i < from.nodes.size(); ++i)
      values[i] = polynomial(from.nodes[i], order);
    const Eigen::VectorXd result = interpolate_nodal(from, values, to);
    ASSERT_EQ(result.size(), static_cast<Eigen::Index>(to.nodes.size()));
    double largest = 0.0, error = 0.0;
    for (std::size_t i = 0; i < to.nodes.size(); ++i) {
      largest = std::max(largest, std::abs(polynomial(to.nodes[i], order)));
      error = std::max(error, std::abs(result[i] - polynomial(to.nodes[i], order)));
    }
    EXPECT_LE(error, 1e-12 * largest) << "order " << order;
  }
}

TEST(Prolongation, NodeOutsideTakesTheNearbyBoundaryValue) {
  // A target node 1 um left of the axis (outside every triangle) of a field that varies with z
  // only (A = z in mm): it takes the value of the closest triangle at a point of its edge on the
  // axis; the barycentric clipping moves that point by at most the node's distance to the edge
  // times the triangle's aspect (about 1), so the reference is z = 3.25 mm within 1e-3 mm.
  const test::PotCore core;
  const mesh::Mesh from = test::pot_core_mesh(core, 2.0, 2);
  Eigen::VectorXd values(static_cast<Eigen::Index>(from.nodes.size()));
  for (std::size_t i = 0; i < from.nodes.size(); ++i) values[i] = 1e3 * from.nodes[i].z;
  mesh::Mesh to;
  to.nodes = {{-1e-6, 3.25e-3}};
  const Eigen::VectorXd result = interpolate_nodal(from, values, to);
  EXPECT_NEAR(result[0], 3.25, 1e-3);
}

/// The pot core at 2 A (partly saturated post) on a P2 mesh with `per_mm` cells per millimetre.
MagnetostaticSolver pot_core_solver(double per_mm, const SolveOptions& options) {
  const test::PotCore core;
  return MagnetostaticSolver(test::pot_core_problem(test::aisi1010(), 400, 2.0, 2),
                             test::pot_core_mesh(core, per_mm, 2), options);
}

TEST(NestedSolve, GivesTheFineSolversLambdaAndInductance) {
  // Reference: the same fine solver's plain solve from A = 0 (about 3e4 unknowns). Both stop at
  // Newton's relative residual 1e-8 and solve dlambda/dI to 1e-12, so lambda and dlambda/dI
  // agree to 1e-8 relative (the tolerance of issue 35), for the default factor reuse and for
  // frozen tangents (CG with the first factor, up to 30 iterations, no refactorisation on a
  // changed tangent).
  const test::PotCore core;
  const double per_mm = 3.5;
  const std::vector<mesh::Mesh> coarser = {test::pot_core_mesh(core, per_mm / 4.0, 2),
                                           test::pot_core_mesh(core, per_mm / 2.0, 2)};
  MagnetostaticSolver plain = pot_core_solver(per_mm, {});
  const Solution reference = plain.solve();
  SolveOptions frozen;
  frozen.reuse.refactor_change = std::numeric_limits<double>::infinity();
  frozen.reuse.max_iterations = 30;
  for (const SolveOptions& options : {SolveOptions{}, frozen}) {
    MagnetostaticSolver fine = pot_core_solver(per_mm, options);
    const Solution nested = solve_nested(fine, coarser, {2.0});
    EXPECT_NEAR(nested.flux_linkage[0], reference.flux_linkage[0],
                1e-8 * reference.flux_linkage[0]);
    EXPECT_NEAR(nested.incremental_inductance[0], reference.incremental_inductance[0],
                1e-8 * reference.incremental_inductance[0]);
    EXPECT_LE(nested.newton.residual_history.back(), 1e-8);
  }
}

TEST(NestedSolve, WithoutCoarseMeshesIsThePlainSolve) {
  // Reference: a plain solve of an identical solver; no coarse mesh means the same Newton from
  // A = 0, so bitwise the same lambda.
  MagnetostaticSolver a = pot_core_solver(1.5, {}), b = pot_core_solver(1.5, {});
  EXPECT_EQ(solve_nested(a, {}, {2.0}).flux_linkage[0], b.solve().flux_linkage[0]);
}

TEST(NestedSolve, CoarseFailureFallsBackToThePlainSolve) {
  // Reference: a plain solve of an identical solver. A coarse tolerance of 0 cannot be met (the
  // residual stagnates at rounding), so the coarse Newton throws ConvergenceError; the nested
  // solve then runs the fine Newton from A = 0: bitwise the plain solve's lambda.
  const test::PotCore core;
  MagnetostaticSolver a = pot_core_solver(1.5, {}), b = pot_core_solver(1.5, {});
  NestedOptions impossible;
  impossible.coarse_tolerance = 0.0;
  const Solution nested = solve_nested(a, {test::pot_core_mesh(core, 0.75, 2)}, {2.0}, impossible);
  EXPECT_EQ(nested.flux_linkage[0], b.solve().flux_linkage[0]);
}

}  // namespace
}  // namespace rheomag::magnetostatics
