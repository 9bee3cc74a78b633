#pragma once
// Evaluating one design: override the base case's keys, re-read it as a case file, mesh (or
// reuse the mesh of an identical geometry), solve, and format its CSV row.

#include <deque>
#include <filesystem>
#include <memory>
#include <string>

#include "magnetostatics/solver.hpp"
#include "mesh/mesh.hpp"
#include "optimise/sweep_row.hpp"

namespace rheomag::optimise {

/// The text of the base case with the design's values set (what parse_case reads).
std::string design_case_text(const SweepSpec& spec, const Design& design);

/// A string that is equal for two closed problems exactly when the mesher gets the same input
/// (PSLG points, segments, region seeds and sizes, order, elements across gaps, mesh options).
std::string geometry_signature(const magnetostatics::Problem& closed,
                               const mesh::MeshOptions& options);

/// Evaluates designs one at a time (one evaluator per worker thread). Meshes are reused: the
/// last kMeshCacheSize geometries are kept, so designs that change only currents, turns,
/// materials or later-link keys (flow, ...) skip domain meshing. Consecutive designs that differ
/// only in circuit currents also share the solver (dof map, assembler, symbolic analysis) with
/// its numeric factorisation discarded, and every other design gets a fresh solver, so a
/// design's numbers never depend on which designs the worker solved before: the CSV is
/// identical for any --jobs, shard or resume.
class SweepEvaluator {
 public:
  /// `vtu_dir` empty: no .vtu files; otherwise one <vtu_dir>/design-<id>.vtu per ok design.
  SweepEvaluator(const SweepSpec& spec, const RowLayout& layout, std::filesystem::path vtu_dir);
  /// The design's CSV row: an ok row, or an error row with the message of whatever failed
  /// (bad case values, impossible geometry, meshing, non-convergence). Never throws for the
  /// design's own failures.
  std::string row(const Design& design);
  /// Meshes generated and reused so far.
  long long meshes_built() const { return built_; }
  long long meshes_reused() const { return reused_; }
  /// Designs solved with the previous design's solver (only the currents changed).
  long long solvers_reused() const { return solvers_reused_; }

  /// Geometries whose mesh is kept per evaluator.
  static constexpr std::size_t kMeshCacheSize = 4;

 private:
  std::string solve_row(const Design& design);
  const SweepSpec* spec_;
  const RowLayout* layout_;
  std::filesystem::path vtu_dir_;
  magnetostatics::SolveOptions options_;
  std::deque<std::pair<std::string, std::shared_ptr<const mesh::Mesh>>> meshes_;
  long long built_ = 0;
  long long reused_ = 0;
  std::string solver_key_;  // the design's case text without its current axes
  std::unique_ptr<magnetostatics::MagnetostaticSolver> solver_;
  long long solvers_reused_ = 0;
};

/// Path of a design's .vtu file in `vtu_dir` ("design-000042.vtu").
std::filesystem::path design_vtu_path(const std::filesystem::path& vtu_dir, long long id);

}  // namespace rheomag::optimise
