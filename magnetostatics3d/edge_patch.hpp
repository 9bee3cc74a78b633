#pragma once
// Patches of edge unknowns for local Newton corrections of the 3D problem (nonlinear
// elimination at saturating corners, magnetostatics/local_newton.hpp).

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "magnetostatics/local_newton.hpp"
#include "magnetostatics3d/edge_solver.hpp"

namespace rheomag::magnetostatics3d {

/// Tetrahedra around each edge, in compressed rows: those of edge e are
/// tets[start[e]] .. tets[start[e + 1] - 1], ascending.
struct EdgeTetrahedra {
  std::vector<int> start;
  std::vector<int> tets;
};

/// The tetrahedra around every edge of `mesh`.
EdgeTetrahedra edge_tetrahedra(const TetMesh& mesh);

/// The unknowns of EdgeSolver's problem (its dofs) around some seeds, with every tetrahedron
/// that touches them. Its values live in `x` (per dof) and, alike, in `a` (per edge).
class EdgePatch : public magnetostatics::LocalPatch {
 public:
  /// The seeds (dofs) grown by `layers` rings of tetrahedra. `load` is per dof at the solve's
  /// currents. `regularise` adds 1e-8 of the diagonal to the tangent: without a gauge a patch
  /// holds the gradients of its inner nodes, where the curl-curl tangent is singular (they do
  /// not change B, so the shift moves only the gauge of the step).
  EdgePatch(const EdgeSolver& solver, const EdgeTetrahedra& around, const Eigen::VectorXd& load,
            Eigen::VectorXd& x, Eigen::VectorXd& a, const std::vector<int>& seeds, int layers,
            bool regularise);

  const std::vector<int>& rows() const override { return rows_; }
  int unknowns() const override { return unknowns_; }
  Eigen::VectorXd values() const override;
  void set_values(const Eigen::VectorXd& values) override;
  void assemble(Eigen::VectorXd& internal,
                Eigen::SparseMatrix<double, Eigen::ColMajor, int>* tangent) const override;
  double potential() const override;

 private:
  const EdgeSolver& solver_;
  const Eigen::VectorXd& load_;
  Eigen::VectorXd& x_;
  Eigen::VectorXd& a_;
  bool regularise_;
  int unknowns_ = 0;
  std::vector<int> rows_;       // dofs: the unknowns (ascending), then the other rows
  std::vector<int> elements_;   // tetrahedra touching an unknown, ascending
  std::vector<int> local_row_;  // per dof: its position in rows_, -1 outside
};

}  // namespace rheomag::magnetostatics3d
