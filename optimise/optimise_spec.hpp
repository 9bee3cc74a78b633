#pragma once
// The [optimise] table of a case file: design variables (case keys with bounds), constraints on
// computed quantities, the objective and the operating point. Format: docs/optimisation.md.

#include <cmath>
#include <string>
#include <vector>

#include "magnetostatics/case_file.hpp"

namespace rheomag::optimise {

/// One design variable: a numeric case key (dotted path) varied between bounds (file units).
struct DesignVariable {
  std::string key;  ///< e.g. "geometry.neck_radius"
  double lower = 0.0, upper = 0.0;
  double initial = 0.0;  ///< the case's value
};

/// One inequality constraint lower <= quantity <= upper (SI units; +-inf when absent).
struct Constraint {
  std::string quantity;
  double lower = -INFINITY, upper = INFINITY;
  std::string where;  ///< "file:line: optimise.constraint[i]" for reports
};

/// Everything the optimiser needs from the case.
struct OptimiseSpec {
  std::vector<DesignVariable> variables;
  std::vector<Constraint> constraints;
  std::string objective = "dp_on";  ///< a quantity name
  bool maximise = true;
  double current = 1.0;     ///< on-state coil current [A]
  double flow = 0.0;        ///< design flow rate [m^3/s]
  int max_iterations = 40;  ///< Ipopt iterations
  double tolerance = 1e-4;  ///< Ipopt relative tolerance on the scaled problem
  double step = 1e-3;       ///< central-difference step as a fraction of each bound range
};

/// The quantities a design is evaluated for (names usable as objective and in constraints),
/// with their SI units.
const std::vector<std::pair<std::string, std::string>>& quantity_units();

/// Reads and checks the [optimise] table of a case: unknown design keys (with the closest key),
/// reversed bounds, initial values outside the bounds, non-positive bounds of lengths and
/// counts, unknown quantities (with the closest name) -> InputError naming file, line and key.
OptimiseSpec read_optimise_spec(const magnetostatics::Case& c);

}  // namespace rheomag::optimise
