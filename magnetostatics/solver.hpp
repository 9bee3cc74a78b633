#pragma once
// The magnetostatic solver: owns a mesh, its dof map, the assembler and the Cholesky
// factorisation, and solves for any set of circuit currents (analysis reused across solves).

#include <Eigen/CholmodSupport>
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "case/problem.hpp"
#include "magnetostatics/assembly.hpp"
#include "magnetostatics/dof_map.hpp"
#include "magnetostatics/frozen_factor.hpp"
#include "magnetostatics/newton.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesher.hpp"

namespace rheomag::magnetostatics {

/// When a Newton step (or dlambda/dI) is solved by conjugate gradients preconditioned with the
/// last factorisation instead of factorising its own Jacobian.
struct FactorReuse {
  /// Factorise when the tangent's stored values moved more than this (relative Euclidean norm)
  /// from the factorised ones; infinity: always try CG with the old factor first.
  double refactor_change = 1e-3;
  /// Most CG iterations with the old factor; a CG that cannot reach its tolerance within them
  /// gives up (after 3 iterations, from its rate) and the Jacobian is factorised.
  int max_iterations = 8;
};

/// Settings of a solve.
struct SolveOptions {
  NewtonOptions newton;                ///< Newton tolerances and limits
  FactorReuse reuse;                   ///< frozen tangents: CG with an older factorisation
  bool incremental_inductance = true;  ///< compute dlambda/dI (one extra factorisation)
  /// Meshing, used by solve_problem only (its order and min_gap_elements come from the Problem).
  mesh::MeshOptions mesh;
  /// solve_problem only: meshes with more nodes than this are solved by nested iteration
  /// (nested_solve.hpp: coarser copies of the mesh first, each a quarter of the nodes of the
  /// next, down to about nested_above / 10); the same solution to Newton's tolerance in fewer
  /// fine Newton steps (docs/performance.md, round 5). 0: never.
  long nested_above = 200'000;
};

/// One solution: the nodal vector potential and the circuit quantities.
struct Solution {
  std::vector<double> currents;                ///< per circuit [A]
  Eigen::VectorXd a;                           ///< A_phi (or A_z) at every mesh node [Wb/m]
  NewtonReport newton;                         ///< iterations, residual history
  std::vector<double> flux_linkage;            ///< per circuit lambda [Wb]
  std::vector<double> incremental_inductance;  ///< per circuit dlambda/dI [H], if requested
  /// Per circuit dA/dI at the reduced dofs [Wb/(m A)] (K_t^-1 F, the solve behind
  /// incremental_inductance; free dofs when no periodic pair is constrained), if requested.
  std::vector<Eigen::VectorXd> incremental_field;
  /// R(A) at the solution over the reduced dofs, what Newton left (incremental solves only).
  Eigen::VectorXd residual;
  double seconds = 0.0;  ///< wall time of the solve
};

/// The flux density of one fluid gap at a sweep point (the quantities of docs/quantities.md).
struct SweepGap {
  std::string name;
  double b_avg = 0.0;          ///< B_avg: |B| averaged over the gap's area [T]
  double b_max_midline = 0.0;  ///< B_max_midline: largest |B| along the gap's mid-line [T]
  double b_max_area = 0.0;     ///< B_max_area: largest |B| anywhere in the gap (corners) [T]
};

/// One row of a current sweep.
struct SweepPoint {
  double current = 0.0;                 ///< [A]
  double flux_linkage = 0.0;            ///< [Wb]
  double secant_inductance = 0.0;       ///< lambda / I [H] (incremental at I = 0)
  double incremental_inductance = 0.0;  ///< dlambda/dI [H]
  int newton_iterations = 0;
  std::vector<SweepGap> gaps;  ///< filled by sweep_with_gaps (results.hpp); empty otherwise
};

/// Nonlinear magnetostatic finite-element solver on a fixed mesh (see element_kernel.hpp for the
/// weak form). Newton with the exact Jacobian, a line search on the residual norm or the field
/// energy, and local corrections at saturating corners (newton.hpp, local_correction.hpp);
/// CHOLMOD supernodal Cholesky whose symbolic analysis is done once in the constructor and reused
/// by every factorisation of every solve (CHOLMOD's OpenMP regions run serially,
/// serial_openmp.hpp; huge pages for the factor, huge_pages.hpp). A Newton step whose Jacobian
/// is within FactorReuse::refactor_change of the last factorised one is solved by conjugate
/// gradients preconditioned with that factorisation (to Newton's forcing tolerance); otherwise, or
/// after a CG solve that failed or took more than FactorReuse::max_iterations / 2 iterations, the
/// Jacobian is factorised.
class MagnetostaticSolver {
 public:
  /// Takes the problem (regions, materials, circuits, boundaries) and a mesh of it
  /// (mesh.region indexes problem.regions). Throws InputError for inconsistent data.
  MagnetostaticSolver(cases::Problem problem, mesh::Mesh mesh, SolveOptions options = {});
  MagnetostaticSolver(const MagnetostaticSolver&) = delete;
  MagnetostaticSolver& operator=(const MagnetostaticSolver&) = delete;

  /// Solves for the given current per circuit [A], from `initial_guess` (all nodes) or A = 0.
  /// Throws ConvergenceError if Newton fails.
  Solution solve(const std::vector<double>& currents,
                 const Eigen::VectorXd* initial_guess = nullptr);
  /// As solve(currents, initial_guess), with the incremental inductance and field whatever
  /// SolveOptions::incremental_inductance says, and, when warm started, without local
  /// corrections: from a nearby state (the quasi-static table's tangent predictions) they rarely
  /// pay and cost more than they save (docs/performance.md, round 8).
  Solution solve_incremental(const std::vector<double>& currents,
                             const Eigen::VectorXd* initial_guess = nullptr);
  /// Solves with the currents of Problem::circuits.
  Solution solve();
  /// lambda(I) and L(I) of circuit `circuit` for each current (other circuits at their problem
  /// currents), each solve warm-started from the previous one, same factorisation analysis.
  /// `each`, when given, is called with every point's solution and row (e.g. to add its gaps).
  std::vector<SweepPoint> sweep(int circuit, const std::vector<double>& currents,
                                const std::function<void(const Solution&, SweepPoint&)>& each = {});
  /// A copy of the factorisation of the tangent at the last incremental solve's solution (the
  /// one behind its dlambda/dI; factorised now when that was solved with an older factor), to
  /// solve nearby systems with after this solver has moved on. Null when there is none: no solve
  /// since the tangent was last assembled elsewhere, or no unknowns.
  std::shared_ptr<const FrozenFactor> freeze_tangent_factor();
  /// With `factorise` the incremental solves' dA/dI take a factorisation of the tangent at the
  /// solution instead of conjugate gradients preconditioned with an older one: for a caller that
  /// freezes that factorisation next (freeze_tangent_factor would factorise it anyway), the CG
  /// iterations are saved. Default false.
  void factorise_incremental_tangent(bool factorise) { factorise_incremental_ = factorise; }
  /// Drops the numeric factorisation but keeps the symbolic analysis: the next solve gives
  /// bitwise what a newly constructed solver of the same problem and mesh would give.
  void discard_factorisation();

  const cases::Problem& problem() const { return problem_; }
  const mesh::Mesh& mesh() const { return mesh_; }
  const DofMap& dofs() const { return dofs_; }
  const Assembler& assembler() const { return *assembler_; }
  const SolveOptions& options() const { return options_; }
  /// Unit-current source / flux-linkage vector of circuit c over all nodes.
  const Eigen::VectorXd& circuit_source(int c) const { return sources_[c]; }
  /// Current-independent source over all nodes: magnets, fixed J, point currents.
  const Eigen::VectorXd& fixed_source() const { return fixed_source_; }
  /// True when circuit c's flux linkage does not depend on the gauge: always, unless the gauge
  /// was fixed by pinning a node (DofMap::gauge_node) and the circuit's signed turns do not
  /// cancel (a one-sided circuit: lambda shifts by (turns x depth) x the arbitrary constant).
  bool flux_linkage_gauge_free(int c) const;
  /// Residual R(A) over the free dofs for nodal A and currents (for tests and diagnostics).
  Eigen::VectorXd residual(const Eigen::VectorXd& a, const std::vector<double>& currents) const;
  /// R(A) as above and, in the same assembly, the lower-triangular exact tangent dR/dA (free
  /// dofs) into `tangent`.
  Eigen::VectorXd residual(const Eigen::VectorXd& a, const std::vector<double>& currents,
                           SparseMatrix& tangent) const;
  /// Lower-triangular exact tangent dR/dA (free dofs) at nodal A.
  SparseMatrix tangent(const Eigen::VectorXd& a) const;
  /// Nodal values of A from the free dofs `x` (prescribed values at the other nodes).
  Eigen::VectorXd free_to_nodes(const Eigen::VectorXd& x) const;
  /// The free dofs' values of nodal `a`.
  Eigen::VectorXd nodes_to_free(const Eigen::VectorXd& a) const;
  /// Number of numeric factorisations done so far (symbolic analysis is done once).
  int factorizations() const { return factorizations_; }
  /// Assemblies of the residual (with or without the tangent) done by solves so far.
  int assemblies() const { return assemblies_; }
  /// Conjugate-gradient iterations done with a reused factorisation so far.
  int reuse_iterations() const { return reuse_iterations_; }

  /// Most CG iterations accepted with a reused factorisation before refactorising (the default
  /// of FactorReuse::max_iterations).
  static constexpr int kReuseIterations = FactorReuse{}.max_iterations;
  /// Relative change of the tangent's values (Euclidean norm over the stored entries) since the
  /// last factorisation above which the Jacobian is factorised rather than solved by CG with the
  /// old factor (measured: 4e-5 -> 3 CG iterations, 4e-4 -> 6, 2e-3 -> no convergence in 8; a
  /// CG attempt that cannot converge gives up after about 3 iterations; the default of
  /// FactorReuse::refactor_change).
  static constexpr double kRefactorChange = FactorReuse{}.refactor_change;

 private:
  class System;
  Solution solve_with(const std::vector<double>& currents, const Eigen::VectorXd* initial_guess,
                      bool incremental, bool local_corrections = true);
  Eigen::VectorXd nodal_source(const std::vector<double>& currents) const;  // all nodes
  void check_compatible(const Eigen::VectorXd& nodal) const;  // InputError if net current != 0
  void prepare_jacobian(const Eigen::VectorXd& a_nodes);
  /// R and the tangent at a_nodes (into free_tangent_ when constrained, else tangent_).
  void assemble_residual_tangent(const Eigen::VectorXd& a_nodes, Eigen::VectorXd& r);
  void factorize_tangent();
  /// The assembled residual at A = 0 without the sources (magnets, prescribed A; free dofs): no
  /// current changes it, so it is assembled once per solver.
  const Eigen::VectorXd& zero_field_load();
  SparseMatrix reduce_tangent(const SparseMatrix& lower) const;      // lower(T^T K T)
  Eigen::VectorXd reduced_to_nodes(const Eigen::VectorXd& x) const;  // Newton unknowns -> nodes
  Eigen::VectorXd nodes_to_reduced(const Eigen::VectorXd& a) const;
  Eigen::VectorXd reduced_source(const Eigen::VectorXd& nodal) const;  // T^T (free rows)
  Eigen::VectorXd solve_jacobian(const Eigen::VectorXd& rhs, double tolerance,
                                 double functional_tolerance = 0.0);
  Eigen::VectorXd solve_factorized(const Eigen::VectorXd& rhs);

  cases::Problem problem_;
  mesh::Mesh mesh_;
  SolveOptions options_;
  DofMap dofs_;
  std::unique_ptr<Assembler> assembler_;
  std::vector<Eigen::VectorXd> sources_;
  Eigen::VectorXd fixed_source_;  // all nodes
  SupernodalCholesky cholesky_;
  SparseMatrix tangent_;             // the matrix Newton factorises (reduced when constrained)
  SparseMatrix free_tangent_;        // constrained: the assembled free-dof tangent
  Eigen::VectorXd factored_values_;  // values of the factorised tangent
  Eigen::VectorXd tangent_nodes_;    // nodal A of the last assembled tangent
  bool tangent_assembled_ = false;   // ... which is still in free_tangent_ or tangent_
  bool linear_ = true;
  bool factorized_linear_ = false;      // linear problem: the one factorisation stays valid
  bool has_factor_ = false;             // cholesky_ holds a factorisation of some tangent
  bool factor_current_ = false;         // ... of the current tangent_
  bool refactor_next_ = true;           // the last reuse was slow: factorise at the next Jacobian
  bool factorise_incremental_ = false;  // factorise_incremental_tangent
  int factorizations_ = 0;
  int assemblies_ = 0;
  std::optional<Eigen::VectorXd> zero_field_load_;  // zero_field_load(), once assembled
  int reuse_iterations_ = 0;
};

}  // namespace rheomag::magnetostatics
