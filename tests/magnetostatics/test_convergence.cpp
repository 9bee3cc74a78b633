// Manufactured solution on an axisymmetric domain that touches the axis: L2 convergence rates.
//
// Domain [0, 1] x [0, 1] in (r, z), nu = nu0, exact A_phi = r (1 - r^2) sin(pi z) (odd in r,
// A/r smooth, A = 0 on r = 1, z = 0, z = 1 and on the axis). Source
// J = curl(nu curl(A e_phi)) . e_phi = nu0 sin(pi z) (8 r + pi^2 (r - r^3)).
// Reference: a priori estimates for Lagrange elements of order p: |A - A_h|_L2 = O(h^{p+1}),
// |B - B_h|_L2 = O(h^p). Tolerance: measured rate within 0.2 of theory (issue 2).

#include <gtest/gtest.h>

#include <Eigen/CholmodSupport>
#include <cmath>
#include <numbers>

#include "core/constants.hpp"
#include "magnetostatics/assembly.hpp"
#include "magnetostatics/dof_map.hpp"
#include "magnetostatics/element_kernel.hpp"
#include "tests/magnetostatics/structured_mesh.hpp"

namespace rheomag::magnetostatics {
namespace {

constexpr double kPi = std::numbers::pi;

double exact_a(double r, double z) {
  return r * (1 - r * r) * std::sin(kPi * z);
}
double exact_br(double r, double z) {
  return -r * (1 - r * r) * kPi * std::cos(kPi * z);
}
double exact_bz(double r, double z) {
  return (2 - 4 * r * r) * std::sin(kPi * z);
}
double source(double r, double z) {
  return kNu0 * std::sin(kPi * z) * (8 * r + kPi * kPi * (r - r * r * r));
}

cases::Problem unit_square_problem(int order) {
  cases::Problem p;
  p.symmetry = cases::Symmetry::axisymmetric;
  p.order = order;
  p.geometry.regions.push_back({{0.5, 0.5}, "air"});
  p.regions.push_back({0, -1, 0.0});
  p.materials.push_back({"air", 1.0, {}, 0.0, "vacuum"});
  p.boundaries.push_back({"zero", cases::BoundaryKind::prescribed_a, 0.0, 0.0, 0.0});
  p.outer = cases::OuterBoundary::none;
  return p;
}

/// L2 errors of A and of B over the meridian plane for an n x n mesh.
std::array<double, 2> errors(int order, int n) {
  const cases::Problem problem = unit_square_problem(order);
  const auto grid = test::uniform(0.0, 1.0, n);
  const mesh::Mesh mesh =
      test::structured_mesh(grid, grid, order, [](double, double) { return 0; }, {-1, 0, 0, 0});
  const DofMap dofs = build_dof_map(mesh, problem);
  const Assembler assembler(problem, mesh, dofs);
  SparseMatrix k = assembler.pattern();
  Eigen::VectorXd zero = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh.nodes.size())), r;
  assembler.assemble(zero, r, &k);

  // Load: integral J v dV with the manufactured J at the quadrature points.
  Eigen::VectorXd load = Eigen::VectorXd::Zero(dofs.free_count());
  const int m = mesh.nodes_per_triangle();
  ElementQuadrature q;
  for (int e = 0; e < static_cast<int>(mesh.triangles.size()); ++e) {
    assembler.quadrature(e, q);
    for (int p = 0; p < q.points; ++p) {
      for (int i = 0; i < m; ++i) {
        const int d = dofs.dof_of_node[mesh.triangles[e][i]];
        if (d >= 0) load[d] += q.weight[p] * source(q.r[p], q.z[p]) * q.n[p][i];
      }
    }
  }
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> cholesky(k);
  EXPECT_EQ(cholesky.info(), Eigen::Success);
  const Eigen::VectorXd x = cholesky.solve(load);
  Eigen::VectorXd a = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh.nodes.size()));
  for (int d = 0; d < dofs.free_count(); ++d) a[dofs.node_of_dof[d]] = x[d];

  double error_a = 0.0, error_b = 0.0;
  double a_local[kMaxElementNodes];
  for (int e = 0; e < static_cast<int>(mesh.triangles.size()); ++e) {
    assembler.quadrature(e, q);
    for (int i = 0; i < m; ++i) a_local[i] = a[mesh.triangles[e][i]];
    for (int p = 0; p < q.points; ++p) {
      double ah = 0.0;
      for (int i = 0; i < m; ++i) ah += q.n[p][i] * a_local[i];
      const auto b = element_b(q, p, a_local);
      const double rr = q.r[p], zz = q.z[p];
      error_a += q.area_weight[p] * std::pow(ah - exact_a(rr, zz), 2);
      error_b += q.area_weight[p] *
                 (std::pow(b[0] - exact_br(rr, zz), 2) + std::pow(b[1] - exact_bz(rr, zz), 2));
    }
  }
  return {std::sqrt(error_a), std::sqrt(error_b)};
}

void expect_rates(int order, int coarse) {
  const auto e1 = errors(order, coarse);
  const auto e2 = errors(order, 2 * coarse);
  const auto e3 = errors(order, 4 * coarse);
  const double rate_a = std::log2(e2[0] / e3[0]);
  const double rate_b = std::log2(e2[1] / e3[1]);
  std::printf("P%d: L2(A) %.3e %.3e %.3e rate %.3f; L2(B) %.3e %.3e %.3e rate %.3f\n", order, e1[0],
              e2[0], e3[0], rate_a, e1[1], e2[1], e3[1], rate_b);
  EXPECT_NEAR(rate_a, order + 1, 0.2);
  EXPECT_NEAR(rate_b, order, 0.2);
  EXPECT_LT(e2[0], e1[0]);
}

TEST(Convergence, LinearElementsRatesTwoAndOne) {
  expect_rates(1, 16);
}

TEST(Convergence, QuadraticElementsRatesThreeAndTwo) {
  expect_rates(2, 8);
}

}  // namespace
}  // namespace rheomag::magnetostatics
