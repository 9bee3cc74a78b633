#pragma once
// `rheomag optimise`: the case's [optimise] problem solved by Ipopt with central-difference
// gradients on the morphed mesh; writes the optimal case, a history CSV and the optimum's .vtu.

#include <filesystem>
#include <string>
#include <vector>

#include "magnetostatics/case_file.hpp"
#include "optimise/optimise_evaluate.hpp"
#include "optimise/optimise_spec.hpp"

namespace rheomag::optimise {

/// One constraint at one design.
struct ConstraintStatus {
  Constraint constraint;
  double value = 0.0;
  bool satisfied = true;  ///< within the bounds up to the feasibility tolerance
  bool active = false;    ///< within 1 % of a bound (the bound limits the design)
};

/// One design with its quantities.
struct DesignReport {
  std::vector<double> x;  ///< design values (file units), in spec.variables order
  Quantities quantities;
  double objective = 0.0;  ///< the objective quantity (SI)
  bool feasible = true;
  std::vector<ConstraintStatus> constraints;
  std::vector<std::string> variables_at_bounds;  ///< keys at a bound (within 0.1 % of the range)
};

/// Where to write and how verbose.
struct OptimiseOptions {
  std::filesystem::path out_dir = ".";
  int print_level = 0;  ///< Ipopt's own output (0 = silent)
};

/// The outcome of an optimisation.
struct OptimiseResult {
  OptimiseSpec spec;
  DesignReport initial, optimal;
  std::string status;  ///< Ipopt's return status
  bool converged = false;
  int iterations = 0;
  int fe_solves = 0;
  int meshes = 0;  ///< 1 + re-meshes (morphs that would have inverted elements)
  double seconds = 0.0;
  std::vector<std::string> conflicts;  ///< infeasible: the constraints that conflict (text)
  std::filesystem::path case_file, history_file, vtu_file;
};

/// Feasibility tolerance: a constraint may be exceeded by this fraction of its bound.
inline constexpr double kFeasibilityTolerance = 1e-3;

/// Reports one design's constraints against the spec.
DesignReport report_design(const OptimiseSpec& spec, const std::vector<double>& x,
                           const Quantities& quantities);

/// Runs the optimisation of `c` (which must have an [optimise] table) and writes
/// <name>_optimal.toml, <name>_history.csv and <name>_optimal.vtu into options.out_dir.
/// InputError for bad input (including an initial design that cannot be evaluated).
OptimiseResult run_optimisation(const magnetostatics::Case& c, const OptimiseOptions& options);

/// The initial-vs-optimal table (quantities, constraint activity, status) as text.
std::string format_summary(const OptimiseResult& result);

}  // namespace rheomag::optimise
