// Validation: a linear permeable sphere in a uniform field (a truly 3D field: B0 across the
// revolution axis). Exact: B inside = 3 mu_r / (mu_r + 2) B0 (uniform); outside B0 plus the field
// of a dipole m = 4 pi a^3 (mu_r - 1)/(mu_r + 2) B0 / mu0 (Jackson, Classical Electrodynamics, 3rd
// ed., section 5.11). The exact exterior A is imposed on the outer sphere.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/constants.hpp"
#include "magnetostatics3d/edge_solver.hpp"
#include "magnetostatics3d/revolve.hpp"

namespace rheomag::magnetostatics3d {
namespace {

constexpr double kPi = std::numbers::pi;

/// Meridian half-disks: a sphere of radius a inside an outer sphere of radius ro (marked).
cases::Problem sphere_problem(double a, double ro, double mu_r, int arc_segments) {
  cases::Problem p;
  mesh::Pslg& g = p.geometry;
  g.source = "sphere";
  auto arc = [&](double radius, int boundary) {
    const int start = static_cast<int>(g.points.size());
    for (int k = 0; k <= arc_segments; ++k) {
      const double t = -0.5 * kPi + kPi * k / arc_segments;
      g.points.push_back({radius * std::cos(t), radius * std::sin(t)});
      if (k > 0) g.segments.push_back({start + k - 1, start + k, boundary});
    }
    return start;
  };
  const int inner = arc(a, -1), outer = arc(ro, 0);
  g.segments.push_back({outer, inner});
  g.segments.push_back({inner + arc_segments, outer + arc_segments});
  g.segments.push_back({inner, inner + arc_segments});
  g.regions.push_back({{0.5 * a, 0.0}, "sphere"});
  g.regions.push_back({{0.5 * (a + ro), 0.0}, "air"});
  cases::Material iron, air;
  iron.name = "iron";
  iron.mu_r = mu_r;
  air.name = "air";
  p.materials = {iron, air};
  p.regions.push_back({0, -1, 0.0});
  p.regions.push_back({1, -1, 0.0});
  p.boundaries.push_back({"outer"});
  return p;
}

/// The average B over the sphere's tetrahedra, solved with `linear`.
Eigen::Vector3d sphere_average(double a, double ro, double mu_r, double b0, LinearSolver3d linear) {
  const cases::Problem p = sphere_problem(a, ro, mu_r, 24);
  const Revolution rev = make_revolution(2 * kPi, 2 * kPi / 48);
  // Tetrahedron edges about a / 4 everywhere: the error of the average is -0.45 %; it falls as
  // O(h^2) (-0.23 % at a / 6, -0.08 % at a / 9; docs/magnetostatics3d.md).
  const double h_in = a / 4, h_out = ro / 8;
  const TetMesh mesh =
      tetrahedralize(revolve(p, rev, {h_in * h_in * h_in / 8.5, h_out * h_out * h_out / 8.5}));
  // Exact exterior potential: uniform B0 along x plus the induced dipole along x.
  const Eigen::Vector3d b_applied(b0, 0, 0);
  const Eigen::Vector3d m = a * a * a * (mu_r - 1) / (mu_r + 2) * b_applied;  // mu0 m / (4 pi)
  auto a_exact = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    return 0.5 * b_applied.cross(x) + m.cross(x) / std::pow(x.norm(), 3);
  };
  Eigen::VectorXd fixed = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh.edges.size()));
  const double gauss[3] = {0.5 - std::sqrt(0.15), 0.5, 0.5 + std::sqrt(0.15)};
  const double weight[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const Eigen::Vector3d x0 = mesh.nodes[mesh.edges[e][0]], x1 = mesh.nodes[mesh.edges[e][1]];
    for (int q = 0; q < 3; ++q)
      fixed[e] += weight[q] * a_exact(x0 + gauss[q] * (x1 - x0)).dot(x1 - x0);
  }
  std::vector<magnetostatics::Reluctivity> laws;
  for (const auto& mat : p.materials) laws.emplace_back(mat);
  EdgeSolver solver(mesh, laws, {0, 1}, fixed, {}, {}, 0, linear);
  const EdgeSolution sol = solver.solve({});
  Eigen::Vector3d inside = Eigen::Vector3d::Zero();
  double volume = 0.0;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    if (mesh.region[t] != 0) continue;
    const double v = mesh.volume(static_cast<int>(t));
    inside += v * sol.b[t];
    volume += v;
  }
  return inside / volume;
}

// Tolerance 1 % (the issue's): the volume average of B over the sphere's tetrahedra against
// B_in = 3 mu_r / (mu_r + 2) B0; transverse components below 1 % of it.
TEST(Sphere, UniformFieldInsideMatchesExactWithinOnePercent) {
  const double a = 0.01, ro = 0.02, mu_r = 10.0, b0 = 1.0;
  const Eigen::Vector3d inside = sphere_average(a, ro, mu_r, b0, LinearSolver3d::cholmod);
  const double exact = 3 * mu_r / (mu_r + 2) * b0;
  EXPECT_NEAR(inside[0] / exact, 1.0, 0.01);
  EXPECT_NEAR(inside[1] / exact, 0.0, 0.01);
  EXPECT_NEAR(inside[2] / exact, 0.0, 0.01);
}

// The same linear problem (prescribed A on the outer sphere, no load) with AMS-preconditioned CG
// on the ungauged system (one set-up for every Newton step of the linear problem, each solved by
// CG to Newton's forcing).
// References: the exact B_in within 1 %, as above, and the CHOLMOD solve within 1e-6 (both are
// the same discrete field up to the linear solvers' tolerance).
TEST(Sphere, AmsGivesTheExactFieldAndCholmodsAverage) {
  const double a = 0.01, ro = 0.02, mu_r = 10.0, b0 = 1.0;
  const Eigen::Vector3d ams = sphere_average(a, ro, mu_r, b0, LinearSolver3d::ams);
  const Eigen::Vector3d cholmod = sphere_average(a, ro, mu_r, b0, LinearSolver3d::cholmod);
  const double exact = 3 * mu_r / (mu_r + 2) * b0;
  EXPECT_NEAR(ams[0] / exact, 1.0, 0.01);
  EXPECT_NEAR(ams[1] / exact, 0.0, 0.01);
  EXPECT_NEAR(ams[2] / exact, 0.0, 0.01);
  EXPECT_LT((ams - cholmod).norm(), 1e-6 * cholmod.norm());
}

}  // namespace
}  // namespace rheomag::magnetostatics3d
