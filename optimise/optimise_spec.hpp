#pragma once
// The [optimise] table of a case file: design variables (case keys with bounds), constraints on
// computed quantities, the objective and the operating point. Format: docs/optimisation.md.

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <utility>
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

/// Quantity name (see quantity_units()) -> value in SI units.
using Quantities = std::map<std::string, double>;

/// One term of the objective: weight x quantity / scale.
struct ObjectiveTerm {
  std::string quantity;
  double weight = 1.0;
  double scale = 1.0;  ///< normaliser; weighted sums: |quantity at the start design|
};

/// The epsilon-constraint sweep of [optimise.pareto]: the objective is optimised while
/// `quantity` (the second objective) is constrained at `points` levels between its extremes.
struct ParetoSpec {
  std::string quantity;
  bool maximise = false;  ///< the second objective's own sense
  int points = 5;         ///< epsilon levels, end points included
};

/// Discrete choices enumerated around the continuous optimisation: a string case key
/// (dotted; "fluid" sets [case] fluid and geometry.fluid_material) and its candidates.
struct DiscreteChoice {
  std::string key;
  std::vector<std::string> values;
};

/// Everything the optimiser needs from the case.
struct OptimiseSpec {
  std::vector<DesignVariable> variables;
  std::vector<Constraint> constraints;
  std::string objective = "dp_on";   ///< a quantity name, or "weighted_sum"
  std::vector<ObjectiveTerm> terms;  ///< objective = sum of terms (one term: the quantity itself)
  bool maximise = true;
  double current = 1.0;             ///< on-state coil current [A]
  double flow = 0.0;                ///< design flow rate [m^3/s]
  int max_iterations = 40;          ///< Ipopt iterations
  double tolerance = 1e-4;          ///< Ipopt relative tolerance on the scaled problem
  double step = 1e-3;               ///< central-difference step as a fraction of each bound range
  double supply_voltage = 0.0;      ///< driver voltage step for rise_time [V] (0: not given)
  double heat_transfer = 10.0;      ///< coil outer surface to ambient [W/(m^2 K)]
  double thermal_resistance = 0.0;  ///< coil to ambient [K/W]; > 0 overrides heat_transfer
  std::optional<ParetoSpec> pareto;
  std::vector<DiscreteChoice> choices;  ///< [optimise] enumerate
};

/// The objective of a design: sum of weight x quantity / scale over the terms. InputError if a
/// quantity is missing or not finite.
double objective_value(const OptimiseSpec& spec, const Quantities& q);

/// Every quantity the spec's objective and constraints use (and the Pareto quantity).
std::vector<std::string> used_quantities(const OptimiseSpec& spec);

/// The quantities a design is evaluated for (names usable as objective and in constraints),
/// with their SI units.
const std::vector<std::pair<std::string, std::string>>& quantity_units();

/// InputError naming `name` and listing the valid names (`where` prefixes the message) if
/// `name` is not a quantity.
void check_quantity_name(const std::string& name, const std::string& where);

/// Reads and checks the [optimise] table of a case: unknown design keys (with the closest key),
/// reversed bounds, initial values outside the bounds, non-positive bounds of lengths and
/// counts, unknown quantities (with the closest name) -> InputError naming file, line and key.
OptimiseSpec read_optimise_spec(const magnetostatics::Case& c);

}  // namespace rheomag::optimise
