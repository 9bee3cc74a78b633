#pragma once
// What `rheomag solve` prints: the results and the optional tables in one JSON object or text.

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "magnetostatics/block_integrals.hpp"
#include "magnetostatics/field_probe.hpp"
#include "magnetostatics/line_integral.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"

namespace rheomag::magnetostatics {

/// One solve's results with the extras asked for on the command line.
struct SolveOutput {
  std::string case_name, case_path, description;
  double mesh_seconds = 0.0;
  std::vector<SweepPoint> sweep;  ///< of the first circuit
  std::vector<FieldProbe> probes;
  std::vector<BlockIntegral> integrals;
  std::vector<LineField> lines;
  /// Files written: (JSON key, path), e.g. {"vtk", "out.vtu"}; in the text as "wrote PATH (what)".
  std::vector<std::pair<std::string, std::string>> files;
};

/// The JSON object of `solve --json`: results_json plus case, mesh_seconds, the written files'
/// keys and the extras (points, sweep, integrals, lines) that are present.
nlohmann::json solve_output_json(const MagnetostaticSolver& solver, const Results& results,
                                 const SolveOutput& output);

/// The terminal summary of the same.
std::string solve_output_text(const MagnetostaticSolver& solver, const Results& results,
                              const SolveOutput& output);

}  // namespace rheomag::magnetostatics
