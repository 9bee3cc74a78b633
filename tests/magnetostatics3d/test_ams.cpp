// The ungauged 3D solve with AMS-preconditioned CG (--linear-solver ams): the discrete gradient
// has no curl and the coil load is discretely divergence-free (what the singular system needs),
// and the nonlinear solve gives CHOLMOD's field in every sector and its flux linkage.

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <string>

#include "case/case_file.hpp"
#include "magnetostatics3d/discrete_gradient.hpp"
#include "magnetostatics3d/solve3d.hpp"
#include "tests/magnetostatics3d/same_gap_field.hpp"

namespace rheomag::magnetostatics3d {
namespace {

/// The small valve with a 2 x 1.5 mm lead slot at 2 A (its 4 mm neck saturates: a nonlinear
/// solve), half model on a coarse swept mesh (43k tetrahedra, 1-3 s per solve).
struct SmallLeadSlot {
  cases::Case c;
  Solve3dOptions options = swept_options();
  SmallLeadSlot() {
    const std::string path = std::string(RHEOMAG_TEST_DATA) + "/magnetostatics3d/small_valve.toml";
    c = cases::parse_case(
        cases::read_input_file(path) +
            "\n[[feature]]\nkind = \"lead_slot\"\nregion = \"core\"\nwidth = 2.0\ndepth = 1.5\n",
        path);
    c.problem.circuits.at(0).current = 2.0;
    options.gap_layers = 1;
    options.region_fraction = 0.5;
    options.facet_angle = 20.0 * std::numbers::pi / 180.0;
    options.fine_angle = 10.0 * std::numbers::pi / 180.0;
  }
  Solve3dResult solve(LinearSolver3d linear) const {
    Solve3dOptions o = options;
    o.linear = linear;
    return solve_problem_3d(c.problem, read_features(c), o);
  }
};

// curl(G phi) = 0 in every tetrahedron for any nodal phi, and G^T f = 0 for the coil load
// f = integral T . curl w (a curl): exact in exact arithmetic. Reference 0; tolerance 1e-12
// relative (rounding of sums of a few dozen terms).
TEST(Ams, GradientHasNoCurlAndTheCoilLoadNoDivergence) {
  const SmallLeadSlot model;
  const Solve3dResult s = model.solve(LinearSolver3d::ams);
  const TetMesh& m = *s.mesh;
  const auto g = discrete_gradient(m);
  const Eigen::VectorXd phi = Eigen::VectorXd::Random(static_cast<Eigen::Index>(m.nodes.size()));
  const Eigen::VectorXd a = g * phi;
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t) {
    const auto c = edge_curls(m, t);
    Eigen::Vector3d curl = Eigen::Vector3d::Zero();
    double scale = 0.0;
    for (int e = 0; e < 6; ++e) {
      curl += a[m.tet_edges[t][e]] * c[e];
      scale = std::max(scale, std::abs(a[m.tet_edges[t][e]]) * c[e].norm());
    }
    ASSERT_LT(curl.norm(), 1e-12 * scale) << t;
  }
  EXPECT_LT(relative_divergence(g, s.solver->load(0)), 1e-12);
}

// The same nonlinear model solved with CHOLMOD on the gauged system and with AMS-preconditioned
// CG on the ungauged one. Both Newton iterations stop at the relative residual 1e-8, so their
// fields differ by about that times the tangent's conditioning (measured: 3e-14 here, 8e-13 on
// the bundled lead-slot half model). Reference: CHOLMOD; tolerance 1e-6 in every 10-degree
// sector of every gap and in the flux linkage.
TEST(Ams, NonlinearLeadSlotModelMatchesCholmodInEverySector) {
  const SmallLeadSlot model;
  const Solve3dResult a = model.solve(LinearSolver3d::cholmod);
  const Solve3dResult b = model.solve(LinearSolver3d::ams);
  ASSERT_EQ(a.results.part, ModelPart::half);
  EXPECT_EQ(b.results.linear_solver, LinearSolver3d::ams);
  EXPECT_GT(b.results.dofs, a.results.dofs);  // no tree removed
  expect_same_gap_field(a.results, b.results, 1e-6);
  EXPECT_GT(b.results.newton_iterations, 1);
  EXPECT_EQ(b.results.factorizations, b.results.newton_iterations);  // one AMS set-up per step
}

}  // namespace
}  // namespace rheomag::magnetostatics3d
