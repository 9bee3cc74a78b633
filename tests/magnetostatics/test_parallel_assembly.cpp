// Parallel (OpenMP) assembly gives bitwise the same residual, tangent and energy for 1, 2 and 3
// threads, and the same values as a plain element-by-element sum.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <vector>

#include "magnetostatics/solver.hpp"
#include "tests/magnetostatics/pot_core.hpp"
#include "tests/magnetostatics/steel.hpp"

namespace rheomag::magnetostatics {
namespace {

struct Assembled {
  Eigen::VectorXd residual;
  SparseMatrix tangent;
  double energy = 0.0;
};

Assembled assemble_with(const Assembler& assembler, const Eigen::VectorXd& a, int threads) {
  const int saved = assembly_threads();
  set_assembly_threads(threads);
  Assembled out;
  out.tangent = assembler.pattern();
  assembler.assemble(a, out.residual, &out.tangent);
  out.energy = assembler.energy(a);
  set_assembly_threads(saved);
  return out;
}

TEST(ParallelAssembly, OneAndTwoThreadsAreBitwiseEqualAndMatchAPlainSum) {
  // Reference 1: the same assembly on one thread, compared bitwise (the chunk colouring fixes
  // the order of the additions to every entry). Reference 2: the residual summed element by
  // element in mesh order from the public element kernel, to 1e-13 of the largest row sum of
  // |element contributions| (the scale of rounding: the linear triangles come from a kept matrix,
  // summed in another order; a chunk assembled twice or left out gives O(1) differences). Mesh: P2
  // pot core at 2/mm, 4 800 triangles (enough chunks to run in parallel), field of the 2 A
  // solution.
  const test::PotCore core;
  MagnetostaticSolver solver(test::pot_core_problem(test::aisi1010(), 400, 2.0, 2),
                             test::pot_core_mesh(core, 2.0, 2));
  const Eigen::VectorXd a = solver.solve().a;
  const Assembler& assembler = solver.assembler();
  const Assembled one = assemble_with(assembler, a, 1);
  const Assembled two = assemble_with(assembler, a, 2);
  const Assembled three = assemble_with(assembler, a, 3);
  EXPECT_TRUE(one.residual == three.residual);
  EXPECT_EQ(one.energy, three.energy);
  EXPECT_TRUE(one.residual == two.residual);
  ASSERT_EQ(one.tangent.nonZeros(), two.tangent.nonZeros());
  for (Eigen::Index k = 0; k < one.tangent.nonZeros(); ++k) {
    ASSERT_EQ(one.tangent.valuePtr()[k], two.tangent.valuePtr()[k]) << "entry " << k;
  }
  EXPECT_EQ(one.energy, two.energy);

  const mesh::Mesh& mesh = solver.mesh();
  const DofMap& dofs = solver.dofs();
  Eigen::VectorXd plain = Eigen::VectorXd::Zero(dofs.free_count());
  Eigen::VectorXd magnitude = Eigen::VectorXd::Zero(dofs.free_count());
  ElementQuadrature q;
  double a_local[kMaxElementNodes], r_local[kMaxElementNodes];
  double k_local[kMaxElementNodes * kMaxElementNodes];
  std::vector<Eigen::Triplet<double>> entries;  // lower triangle, free dofs
  double energy = 0.0;
  for (int e = 0; e < static_cast<int>(mesh.triangles.size()); ++e) {
    const auto& t = mesh.triangles[e];
    for (int i = 0; i < 6; ++i) a_local[i] = a[t[i]];
    assembler.quadrature(e, q);
    element_residual_tangent(q, a_local, assembler.law(e), r_local, k_local);
    for (int i = 0; i < 6; ++i) {
      if (dofs.dof_of_node[t[i]] < 0) continue;
      plain[dofs.dof_of_node[t[i]]] += r_local[i];
      magnitude[dofs.dof_of_node[t[i]]] += std::abs(r_local[i]);
      for (int j = 0; j < 6; ++j) {
        const int row = dofs.dof_of_node[t[i]], col = dofs.dof_of_node[t[j]];
        if (col >= 0 && row >= col) entries.emplace_back(row, col, k_local[i * 6 + j]);
      }
    }
    energy += element_stored_energy(q, a_local, assembler.law(e));
  }
  const double difference = (plain - one.residual).cwiseAbs().maxCoeff();
  const double scale = magnitude.maxCoeff();
  std::printf("max |r_plain - r_parallel| / max row sum |r_e| = %.2e (max |r| / that: %.2e)\n",
              difference / scale, one.residual.cwiseAbs().maxCoeff() / scale);
  EXPECT_LT(difference, 1e-13 * scale);
  EXPECT_NEAR(energy, one.energy, 1e-13 * std::abs(energy));
  // The tangent, the linear triangles' part included (kept since the constructor).
  ASSERT_GT(assembler.linear_triangles(), 0);
  SparseMatrix plain_tangent(dofs.free_count(), dofs.free_count());
  plain_tangent.setFromTriplets(entries.begin(), entries.end());
  const double tangent_difference =
      (SparseMatrix(plain_tangent - one.tangent)).coeffs().abs().maxCoeff();
  EXPECT_LT(tangent_difference, 1e-13 * plain_tangent.coeffs().abs().maxCoeff());
}

}  // namespace
}  // namespace rheomag::magnetostatics
