#pragma once
// Evaluating one sweep design: the base case with the design's values (typed edits, no text),
// solved by the shared design evaluator (cached meshes), formatted as its CSV row.

#include <filesystem>
#include <string>
#include <vector>

#include "case/case_key.hpp"
#include "design/design_evaluator.hpp"
#include "sweep/row.hpp"

namespace rheomag::sweep {

/// The base case's edits for a design (one per axis).
std::vector<cases::CaseEdit> design_edits(const SweepSpec& spec, const Design& design);

/// Evaluates designs one at a time (one evaluator per worker thread). Meshes are reused: the
/// last DesignEvaluator::kMeshCacheSize geometries are kept, so designs that change only
/// currents, turns, materials or later-layer keys (flow, ...) skip domain meshing. Consecutive
/// designs that differ only in circuit currents also share the solver (dof map, assembler,
/// symbolic analysis) with its numeric factorisation discarded, and every other design gets a
/// fresh solver, so a design's numbers never depend on which designs the worker solved before:
/// the CSV is identical for any --jobs, shard or resume.
class SweepEvaluator {
 public:
  /// `vtu_dir` empty: no .vtu files; otherwise one <vtu_dir>/design-<id>.vtu per ok design.
  SweepEvaluator(const SweepSpec& spec, const RowLayout& layout, std::filesystem::path vtu_dir);
  /// The design's CSV row: an ok row, or an error row with the message of whatever failed
  /// (bad case values, impossible geometry, meshing, non-convergence). Never throws for the
  /// design's own failures.
  std::string row(const Design& design);
  /// Meshes generated and reused so far.
  long long meshes_built() const { return evaluator_.meshes_built(); }
  long long meshes_reused() const { return evaluator_.meshes_reused(); }
  /// Designs solved with the previous design's solver (only the currents changed).
  long long solvers_reused() const { return evaluator_.solvers_reused(); }

 private:
  std::string solve_row(const Design& design);
  const SweepSpec* spec_;
  const RowLayout* layout_;
  std::filesystem::path vtu_dir_;
  design::DesignEvaluator evaluator_;
  std::vector<cases::KeyValue> solver_values_;  ///< non-current axis values of the solver's design
};

/// Path of a design's .vtu file in `vtu_dir` ("design-000042.vtu").
std::filesystem::path design_vtu_path(const std::filesystem::path& vtu_dir, long long id);

}  // namespace rheomag::sweep
