#pragma once
// Global assembly: scatters element kernels into the free-dof residual and sparse tangent.

#include <Eigen/Sparse>
#include <vector>

#include "magnetostatics/dof_map.hpp"
#include "magnetostatics/element_kernel.hpp"
#include "magnetostatics/problem.hpp"
#include "magnetostatics/reluctivity.hpp"
#include "mesh/mesh.hpp"

namespace rheomag::magnetostatics {

/// Sparse matrix type of the tangent: column-major, only the lower triangle is stored.
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Assembles the residual R(A) = K(A) A + (Robin terms) - (sources are added by the caller) and
/// its exact tangent over one mesh. The sparsity pattern and the element-to-matrix scatter map
/// are built once in the constructor and reused for every assembly.
class Assembler {
 public:
  /// Checks that every triangle's region has a material (InputError otherwise).
  Assembler(const Problem& problem, const mesh::Mesh& mesh, const DofMap& dofs);

  /// Free-dof residual of the internal forces plus mixed (Robin) boundary terms at the nodal
  /// values `a` (all nodes, prescribed ones included); also the lower-triangular tangent when
  /// `tangent` is not null (it must be a copy of pattern()).
  void assemble(const Eigen::VectorXd& a, Eigen::VectorXd& residual, SparseMatrix* tangent) const;

  /// The tangent's sparsity pattern (lower triangle, free dofs), values zero.
  const SparseMatrix& pattern() const { return pattern_; }

  /// Source vector of circuit `c` at 1 A, over all nodes: sum over its regions of
  /// (turns / region area) integral N_i dV. Also the flux-linkage functional: lambda_c = F_c . A.
  Eigen::VectorXd circuit_source(int c) const;

  /// Shape functions and B operators of triangle `e`.
  void quadrature(int e, ElementQuadrature& q) const;
  /// Constitutive law of triangle `e`.
  const Reluctivity& law(int e) const { return laws_[material_of_element_[e]]; }
  /// Meridian-plane area of each region [m^2] (index as Problem::regions).
  const std::vector<double>& region_areas() const { return region_area_; }
  /// Energy of the mixed (Robin) boundary terms, integral (c0 A^2 / 2 - c1 A) dw [J]: for the
  /// open boundary (c0 = nu0 / R0, c1 = 0) the exact field energy outside R0 of a dipole field.
  double boundary_energy(const Eigen::VectorXd& a) const;
  /// True when some material has a B-H curve.
  bool nonlinear() const;

 private:
  struct RobinEdge {
    std::array<int, 3> nodes;
    double c0, c1;
  };
  template <class Visit>
  void for_robin_points(const RobinEdge& edge, Visit visit) const;
  void scatter_robin(const Eigen::VectorXd& a, Eigen::VectorXd& residual,
                     SparseMatrix* tangent) const;
  int matrix_offset(int row, int col) const;  // position in pattern_ values, -1 if not stored

  const Problem& problem_;
  const mesh::Mesh& mesh_;
  const DofMap& dofs_;
  std::vector<Reluctivity> laws_;
  std::vector<int> material_of_element_;
  std::vector<double> region_area_;
  std::vector<RobinEdge> robin_edges_;
  SparseMatrix pattern_;
  std::vector<int> element_offsets_;  // nodes^2 per element, row-major local (i, j)
  std::vector<int> robin_offsets_;    // 9 per Robin edge
};

}  // namespace rheomag::magnetostatics
