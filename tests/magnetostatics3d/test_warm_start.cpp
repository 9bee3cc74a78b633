// The 3D Newton iteration started from the revolved 2D solution, with CG on a reused
// factorisation: the start's field is the 2D field exactly where the 2D field is linear in r and
// z, the gauge keeps its curl, and the warm-started solution is the cold-started one.

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <string>

#include "case/case_file.hpp"
#include "magnetostatics3d/gauge.hpp"
#include "magnetostatics3d/plc.hpp"
#include "magnetostatics3d/solve3d.hpp"
#include "magnetostatics3d/warm_start.hpp"
#include "tests/magnetostatics3d/same_gap_field.hpp"
#include "tests/magnetostatics3d/small_lead_slot.hpp"

namespace rheomag::magnetostatics3d {
namespace {

/// The cube [0.2, 1.2] x [0.1, 1.1] x [0, 1] (off the axis) as a PLC with outer faces.
TetMesh cube_mesh() {
  Plc plc;
  plc.source = "cube";
  for (int i = 0; i < 8; ++i) plc.points.emplace_back(0.2 + (i & 1), 0.1 + ((i >> 1) & 1), i >> 2);
  const int faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  for (const auto& f : faces) plc.facets.push_back({{{f[0], f[1], f[2], f[3]}}, FaceKind::outer});
  plc.regions.push_back({Eigen::Vector3d(0.7, 0.6, 0.5), 0, 0.002});
  return tetrahedralize(plc);
}

/// B per tetrahedron of edge values a (Whitney interpolation).
Eigen::Vector3d curl_of(const TetMesh& m, int t, const Eigen::VectorXd& a) {
  const auto c = edge_curls(m, t);
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (int e = 0; e < 6; ++e) b += a[m.tet_edges[t][e]] * c[e];
  return b;
}

// A_phi = B0 r / 2 is the uniform field B0 e_z; it is linear in r (exact on a P1 meridian mesh)
// and A = B0/2 (-y, x, 0) is linear along every edge (the two-point rule is exact), so each
// tetrahedron's B is B0 e_z to rounding. Reference: B0 e_z; tolerance 1e-12 B0.
TEST(WarmStart, RevolvedUniformFieldIsExact) {
  const TetMesh m = cube_mesh();
  mesh::Mesh meridian;
  meridian.nodes = {{0.0, -0.1}, {2.0, -0.1}, {2.0, 1.1}, {0.0, 1.1}};
  meridian.vertex_count = 4;
  meridian.triangles = {{0, 1, 2, 0, 0, 0}, {0, 2, 3, 0, 0, 0}};
  meridian.region = {0, 0};
  const double b0 = 0.7;
  Eigen::VectorXd a_phi(4);
  for (int i = 0; i < 4; ++i) a_phi[i] = 0.5 * b0 * meridian.nodes[i].r;
  const Eigen::VectorXd a = revolved_edge_values(m, meridian, a_phi);
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t)
    EXPECT_LT((curl_of(m, t, a) - Eigen::Vector3d(0, 0, b0)).norm(), 1e-12 * b0) << t;
}

// The gauged unknowns of any edge values that vanish on the fixed edges give the same B in every
// tetrahedron (they differ by a discrete gradient) and 0 on every tree edge (by construction).
// Reference: B of the given values; tolerance 1e-12 of the largest |B|.
TEST(WarmStart, CotreeValuesKeepTheCurl) {
  const TetMesh m = cube_mesh();
  const EdgeDofs dofs = tree_cotree_dofs(m);
  Eigen::VectorXd a = Eigen::VectorXd::Random(static_cast<Eigen::Index>(m.edges.size()));
  for (std::size_t e = 0; e < m.edges.size(); ++e)
    if (dofs.fixed[e]) a[static_cast<Eigen::Index>(e)] = 0.0;
  const Eigen::VectorXd x = cotree_values(m, dofs, a);
  Eigen::VectorXd gauged = Eigen::VectorXd::Zero(a.size());
  for (int d = 0; d < dofs.free_count(); ++d) gauged[dofs.edge_of_dof[d]] = x[d];
  double largest = 0.0;
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t)
    largest = std::max(largest, curl_of(m, t, a).norm());
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t)
    EXPECT_LT((curl_of(m, t, gauged) - curl_of(m, t, a)).norm(), 1e-12 * largest) << t;
}

// The small valve with a lead slot at 2 A (its 4 mm neck saturates: a nonlinear solve), half
// model on a coarse swept mesh, solved from A = 0 with a factorisation per Newton step (the
// first solver, with today's local corrections) and from the revolved 2D solution with CG on a
// reused factorisation. Both converge to Newton's 1e-8; reference: the cold start; tolerance 0.1 %
// in every 10-degree sector of every gap and in the flux linkage. The warm start needs fewer
// factorisations.
TEST(WarmStart, WarmStartedSolveMatchesColdStartInEverySector) {
  const cases::Case c = small_valve_with_lead_slot();
  const Solve3dOptions warm = coarse_swept_options();
  Solve3dOptions cold = warm;
  cold.warm_start = false;
  cold.reuse_iterations = 0;
  const Solve3dResult a = solve_problem_3d(c.problem, read_features(c), cold);
  const Solve3dResult b = solve_problem_3d(c.problem, read_features(c), warm);
  ASSERT_EQ(a.results.part, ModelPart::half);
  expect_same_gap_field(a.results, b.results, 1e-3);
  EXPECT_EQ(a.results.factorizations, a.results.newton_iterations);
  EXPECT_LT(b.results.factorizations, a.results.factorizations);
}

}  // namespace
}  // namespace rheomag::magnetostatics3d
