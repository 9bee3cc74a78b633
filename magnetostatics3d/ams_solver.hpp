#pragma once
// Conjugate gradients preconditioned with hypre's auxiliary-space Maxwell solver (AMS) for the
// ungauged curl-curl systems of lowest-order edge elements.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "magnetostatics/preconditioned_cg.hpp"
#include "magnetostatics3d/tet_mesh.hpp"

namespace rheomag::magnetostatics3d {

/// CG with one AMS cycle as preconditioner (hypre 2.26 in one MPI process: MPI_COMM_SELF, MPI
/// initialised on first use unless the program did). The system is over all edges of the mesh;
/// an edge with a prescribed value keeps only its diagonal (its row and column eliminated), the
/// others form the singular curl-curl operator, whose right-hand sides must be discretely
/// divergence-free (G^T b = 0, discrete_gradient.hpp). A Newton residual is so only to its
/// rounding, which grows relative to it as it falls (|G^T b| / |b| = 3e-6 at the last step of
/// the bundled valve's wedge, where CG then diverged): each right-hand side is first projected
/// out of the kernel, b - G y with G^T G y = G^T b over the nodes off the fixed edges (CG with
/// BoomerAMG, to 1e-10). AMS settings as MFEM's HypreAMS (cycle
/// 13, one l1-scaled symmetric Gauss-Seidel sweep, BoomerAMG on the auxiliary nodal problems
/// with HMIS coarsening, one level of aggressive coarsening, ext+i interpolation of at most 4
/// entries per row, l1-Gauss-Seidel) but strength threshold 0.5 (0.25 took 11 % more
/// iterations on the lead-slot half model, docs/magnetostatics3d.md); no mass term, so the
/// gradient correction is left out.
class AmsCg {
 public:
  /// Matrices are over the edges of `mesh`, `fixed` per edge those with a prescribed value; the
  /// discrete gradient and the node coordinates define the auxiliary spaces.
  AmsCg(const TetMesh& mesh, const std::vector<bool>& fixed);
  ~AmsCg();
  AmsCg(const AmsCg&) = delete;
  AmsCg& operator=(const AmsCg&) = delete;

  /// Takes the values of `matrix` (edges x edges, symmetric, both triangles stored; the first
  /// call fixes the pattern for all later ones) and sets the AMS preconditioner up for it.
  void set_matrix(const Eigen::SparseMatrix<double>& matrix);
  /// Solves A x = b from x = 0 to |A x - b| <= tolerance |b| within max_iterations.
  magnetostatics::CgResult solve(const Eigen::VectorXd& b, double tolerance, int max_iterations,
                                 Eigen::VectorXd& x);
  /// AMS set-ups so far (one per set_matrix).
  int setups() const { return setups_; }
  /// Wall time of the AMS set-ups so far [s].
  double setup_seconds() const { return setup_seconds_; }

 private:
  struct Hypre;
  std::unique_ptr<Hypre> hypre_;
  int setups_ = 0;
  double setup_seconds_ = 0.0;
};

}  // namespace rheomag::magnetostatics3d
