#pragma once
// `rheomag optimise`: the case's [optimise] problem solved by Ipopt with central- or forward-
// difference gradients on the morphed mesh (for each combination of the enumerated discrete
// choices), then the optional epsilon-constraint Pareto front; writes the optimal case, a history
// CSV, the optimum's .vtu and pareto.csv / pareto.png.

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "case/case_file.hpp"
#include "core/progress.hpp"
#include "optimise/evaluate.hpp"
#include "optimise/pareto_front.hpp"
#include "optimise/report.hpp"
#include "optimise/response_check.hpp"
#include "optimise/spec.hpp"

namespace rheomag::optimise {

/// Where to write and how verbose.
struct OptimiseOptions {
  std::filesystem::path out_dir = ".";
  int print_level = 0;  ///< Ipopt's own output (0 = silent)
  /// Reports each Ipopt iteration (out of the spec's iteration limit, a bound) and the FE solves.
  ProgressCallback progress;
};

/// The optimum of one combination of the discrete choices.
struct CombinationResult {
  std::vector<std::pair<std::string, std::string>> choice;  ///< key -> chosen value
  DesignReport optimal;  ///< after rounding counts, on a fresh mesh
  std::string status;    ///< Ipopt's return status
  bool converged = false;
  int iterations = 0;
  int fe_solves = 0;
};

/// The outcome of an optimisation.
struct OptimiseResult {
  OptimiseSpec spec;
  DesignReport initial, optimal;
  std::string status;  ///< Ipopt's return status (of the chosen combination)
  bool converged = false;
  int iterations = 0;
  int fe_solves = 0;
  int meshes = 0;  ///< 1 + re-meshes (morphs that would have inverted elements)
  double seconds = 0.0;
  std::vector<std::string> conflicts;  ///< infeasible: the constraints that conflict (text)
  std::vector<CombinationResult> combinations;  ///< one per enumerated combination (>= 1)
  std::size_t chosen = 0;                       ///< index of the best combination
  std::optional<ParetoFront> pareto;            ///< with [optimise.pareto]
  std::optional<ResponseCheck> response_check;  ///< with response_model = "quasi_static"
  std::filesystem::path case_file, history_file, vtu_file;
  std::vector<std::filesystem::path> pareto_files;  ///< pareto.csv (+ pareto.png)
};

/// Runs the optimisation of `c` (which must have an [optimise] table) and writes
/// <name>_optimal.toml, <name>_history.csv, <name>_optimal.vtu (and with [optimise.pareto]
/// pareto.csv, pareto.png) into options.out_dir. InputError for bad input (including an initial
/// design that cannot be evaluated).
OptimiseResult run_optimisation(const cases::Case& c, const OptimiseOptions& options);

/// "feasible optimum; objective max dp_on: A -> B" with the objective's unit; for a start that
/// breaks a constraint it says so and, when the feasible optimum's objective is worse, that the
/// start's value needs the broken constraints (not a loss of the optimiser).
std::string objective_change_text(const OptimiseResult& result);

/// The initial-vs-optimal table (quantities, constraint activity, status; the combinations and
/// the Pareto front when present) as text; the starting design's feasibility with each broken
/// constraint (value and limit).
std::string format_summary(const OptimiseResult& result);

}  // namespace rheomag::optimise
