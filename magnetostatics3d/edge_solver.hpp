#pragma once
// Nonlinear 3D magnetostatics with lowest-order Nedelec (edge) elements: the vector potential
// A is a combination of Whitney edge functions, B = curl A is constant in each tetrahedron.

#include <Eigen/CholmodSupport>
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "core/enum_names.hpp"
#include "magnetostatics/newton.hpp"
#include "magnetostatics/reluctivity.hpp"
#include "magnetostatics3d/gauge.hpp"
#include "magnetostatics3d/tet_mesh.hpp"

namespace rheomag::magnetostatics3d {

class AmsCg;
struct EdgeTetrahedra;

/// How EdgeSolver solves the linear system of a Newton step.
enum class LinearSolver3d {
  cholmod,  ///< tree-cotree gauge, CHOLMOD supernodal Cholesky (CG on a reused factor)
  ams,      ///< no gauge (all free edges), CG preconditioned with hypre's AMS (ams_solver.hpp)
};

/// Text form of LinearSolver3d (the CLI's --linear-solver).
inline constexpr auto kLinearSolver3dNames = enum_names<LinearSolver3d>(
    {{LinearSolver3d::cholmod, "cholmod"}, {LinearSolver3d::ams, "ams"}});

/// One solution: edge values of A and the flux density per tetrahedron.
struct EdgeSolution {
  std::vector<double> currents;    ///< per circuit [A]
  Eigen::VectorXd a;               ///< line integral of A along every edge [Wb]
  std::vector<Eigen::Vector3d> b;  ///< B per tetrahedron [T]
  magnetostatics::NewtonReport newton;
  int factorizations = 0;  ///< numeric Cholesky factorisations (AMS: set-ups) of this solve
  int cg_iterations = 0;   ///< conjugate-gradient iterations (with a reused factorisation, or
                           ///< with AMS all of them)
  double seconds = 0.0;    ///< wall time of the solve
};

/// Weak form: find A (tangential trace prescribed on condition faces) with
///   sum_t integral_t nu(|B|^2) B . curl w_e dV = sum_c I_c f_ce   for every cotree edge e,
/// f_ce = integral T_c . curl w_e dV the load of circuit c at unit current (coil_source.hpp).
/// Newton with the exact tangent V curl w_i^T (nu + 2 nu' B B^T) curl w_j (symmetric positive
/// definite for a monotone B-H curve) and a line search on the energy (magnetostatics::newton);
/// CHOLMOD supernodal Cholesky, symbolic analysis once. With `reuse_iterations` > 0 a Newton
/// step after the first is solved by conjugate gradients preconditioned with the last
/// factorisation (to Newton's forcing tolerance, NewtonOptions::max_forcing), and its own tangent
/// is factorised only when CG does not converge within that many iterations (modified Newton
/// with an exact-tangent correction: near a good start the tangent barely changes).
/// With LinearSolver3d::ams there is no gauge: every edge off the condition faces is an unknown
/// (A is then determined up to a discrete gradient, B = curl A is not), and each Newton step sets
/// AMS up for its tangent and solves by AMS-preconditioned CG to the forcing tolerance (inexact
/// Newton; `reuse_iterations` does not apply).
class EdgeSolver {
 public:
  /// `laws` per material, `material_of_region` per mesh region, `fixed_values` per edge (used on
  /// fixed edges only), `loads` per circuit (per edge), `reuse_iterations` the CG budget with a
  /// reused factorisation (0: every Newton step factorises its tangent), `linear` how the steps
  /// are solved.
  EdgeSolver(const TetMesh& mesh, std::vector<magnetostatics::Reluctivity> laws,
             std::vector<int> material_of_region, Eigen::VectorXd fixed_values,
             std::vector<Eigen::VectorXd> loads, magnetostatics::NewtonOptions options = {},
             int reuse_iterations = 0, LinearSolver3d linear = LinearSolver3d::cholmod);
  ~EdgeSolver();
  EdgeSolver(const EdgeSolver&) = delete;
  EdgeSolver& operator=(const EdgeSolver&) = delete;

  /// Solves for the given current per circuit [A] from A = 0. Throws ConvergenceError if Newton
  /// fails.
  EdgeSolution solve(const std::vector<double>& currents);
  /// Solves from the edge values `start` (one per edge, e.g. a revolved 2D solution; its gauge
  /// is removed by cotree_values, its fixed edges are ignored).
  EdgeSolution solve(const std::vector<double>& currents, const Eigen::VectorXd& start);

  const TetMesh& mesh() const { return mesh_; }
  const EdgeDofs& dofs() const { return dofs_; }
  /// Load vector of circuit c at unit current (per edge): lambda_c = loads(c) . a.
  const Eigen::VectorXd& load(int c) const { return loads_[c]; }
  /// Reluctivity law of tetrahedron t.
  const magnetostatics::Reluctivity& law(int t) const {
    return laws_[material_of_region_[mesh_.region[t]]];
  }
  /// Flux density of tetrahedron t for edge values a.
  Eigen::Vector3d flux_density(int t, const Eigen::VectorXd& a) const;
  /// Volume of tetrahedron t [m^3].
  double volume(int t) const { return volume_[t]; }
  /// Curls of the six Whitney functions of tetrahedron t (edge_curls).
  const std::array<Eigen::Vector3d, 6>& curls(int t) const { return curl_[t]; }
  /// How the Newton steps' linear systems are solved.
  LinearSolver3d linear_solver() const { return linear_; }
  /// Numeric Cholesky factorisations so far (one per Newton step without a CG budget).
  int factorizations() const { return factorizations_; }
  /// Stored energy sum_t V w(|B|) [J] of the field B per tetrahedron.
  double stored_energy(const std::vector<Eigen::Vector3d>& b) const;

 private:
  class System;
  using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
  Eigen::VectorXd to_edges(const Eigen::VectorXd& x) const;
  int row_of(int edge) const;
  void build_pattern();
  void assemble(const Eigen::VectorXd& a, Eigen::VectorXd* residual, bool tangent);

  const TetMesh& mesh_;
  std::vector<magnetostatics::Reluctivity> laws_;
  std::vector<int> material_of_region_;
  Eigen::VectorXd fixed_values_;
  std::vector<Eigen::VectorXd> loads_;
  magnetostatics::NewtonOptions options_;
  EdgeDofs dofs_;
  std::vector<double> volume_;
  std::vector<std::array<Eigen::Vector3d, 6>> curl_;
  std::vector<std::array<int, 36>> slot_;  // value index in tangent_ of local (i, j), -1 none
  // CHOLMOD: lower triangle over the unknowns; AMS: both triangles over all edges (a fixed edge
  // keeps its diagonal only).
  SparseMatrix tangent_;
  LinearSolver3d linear_ = LinearSolver3d::cholmod;
  std::unique_ptr<AmsCg> ams_;
  std::unique_ptr<EdgeTetrahedra> around_;  // the pattern's and local corrections' adjacency
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> cholesky_;
  int reuse_iterations_ = 0;
  bool nonlinear_ = false;
  bool factorized_ = false;
  int factorizations_ = 0;
  int cg_iterations_ = 0;
};

}  // namespace rheomag::magnetostatics3d
