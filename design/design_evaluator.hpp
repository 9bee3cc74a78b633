#pragma once
// The one pipeline from a design (a typed case) to its solved field, shared by sweeps and the
// optimiser: close the domain, mesh it by the evaluator's policy, solve at the given currents,
// and compute the per-gap and per-circuit results.

#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "case/case_file.hpp"
#include "design/morph_mesh.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"
#include "mesh/mesh.hpp"

namespace rheomag::design {

/// How a design evaluator gets the mesh of each design.
enum class MeshPolicy {
  cached,   ///< the mesh `rheomag solve` makes for the design; the last few geometries kept
  morphed,  ///< the first design's mesh morphed to each design (fixed topology, smooth in the
            ///< dimensions: what gradient-based optimisation needs); re-meshed when a morph fails
};

/// The solved field of one design.
struct EvaluatedField {
  std::shared_ptr<magnetostatics::MagnetostaticSolver> solver;
  magnetostatics::Solution solution;
  magnetostatics::Results results;
};

/// Called with the closed problem and its mesh before the solver is built (e.g. to set the
/// turns of a relaxed wire gauge from the mesh's winding windows).
using ProblemAdjustment = std::function<void(cases::Problem& closed, const mesh::Mesh& mesh)>;

/// A string that is equal for two closed problems exactly when the mesher gets the same input
/// (PSLG points, segments, region seeds and sizes, order, elements across gaps, mesh options).
std::string geometry_signature(const cases::Problem& closed, const mesh::MeshOptions& options);

/// Meshes and solves designs one after the other (one evaluator per worker thread).
class DesignEvaluator {
 public:
  DesignEvaluator(MeshPolicy policy, magnetostatics::SolveOptions options = {});

  /// Solves `design` at `currents` (one per circuit). With `same_problem` (the caller knows
  /// that only the currents differ from the previous design) the previous solver is reused
  /// with its numeric factorisation discarded, so the numbers equal a fresh solver's.
  /// `initial_guess` (nodal A): Newton's start when the design's mesh is a morph with that many
  /// nodes (a nearby design's solution on a mesh of the same topology), else A = 0.
  /// InputError for an invalid design, ConvergenceError when Newton fails.
  const EvaluatedField& solve(const cases::Case& design, const std::vector<double>& currents,
                              bool same_problem = false, const ProblemAdjustment& adjust = {},
                              const Eigen::VectorXd* initial_guess = nullptr);

  /// The field of the last solve().
  const EvaluatedField& last() const { return last_; }
  /// Makes the next solve() generate a fresh mesh (the reference of later morphs).
  void remesh_next() { have_reference_ = false; }
  /// FE solves done so far.
  int fe_solves() const { return fe_solves_; }
  /// Meshes generated so far, reused from the cache, and solvers reused (only currents changed).
  long long meshes_built() const { return built_; }
  long long meshes_reused() const { return reused_; }
  long long solvers_reused() const { return solvers_reused_; }
  /// Counts `n` more FE solves made by the caller on the last field's solver.
  void count_solves(int n) { fe_solves_ += n; }

  /// Geometries whose mesh the cached policy keeps.
  static constexpr std::size_t kMeshCacheSize = 4;

 private:
  std::shared_ptr<const mesh::Mesh> mesh_for(const cases::Problem& closed);

  MeshPolicy policy_;
  magnetostatics::SolveOptions options_;
  std::deque<std::pair<std::string, std::shared_ptr<const mesh::Mesh>>> cache_;
  mesh::Mesh reference_mesh_;
  Breakpoints reference_breakpoints_;
  bool have_reference_ = false;
  EvaluatedField last_;
  int fe_solves_ = 0;
  long long built_ = 0, reused_ = 0, solvers_reused_ = 0;
};

}  // namespace rheomag::design
