#pragma once
// One evaluated design judged against an [optimise] spec: objective, constraint status and
// activity, variables at their bounds.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "optimise/spec.hpp"

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
  design::Quantities quantities;
  double objective = 0.0;  ///< the objective (SI; a weighted sum is dimensionless)
  bool feasible = true;
  std::vector<ConstraintStatus> constraints;
  std::vector<std::string> variables_at_bounds;  ///< keys at a bound (within 0.1 % of the range)
  /// response_model = "quasi_static": response_time by the two transient runs, where checked
  /// (the optimum and the Pareto levels).
  std::optional<double> response_time_transient;
  /// A continuous optimum with every variable on a bound that its objective presses on (Ipopt's
  /// bound multiplier above kVertexMultiplier): a vertex of the box that no nearby design in the
  /// box matches, so the only design at its own objective's level.
  bool strict_vertex = false;
};

/// Smallest bound multiplier (on the scaled program: objective change per unit of the
/// variable's range over its start value) that counts a bound as pressed on: 0.1 %.
inline constexpr double kVertexMultiplier = 1e-3;

/// Feasibility tolerance: a constraint may be exceeded by this fraction of its bound.
inline constexpr double kFeasibilityTolerance = 1e-3;

/// Reports one design's constraints against the spec.
DesignReport report_design(const OptimiseSpec& spec, const std::vector<double>& x,
                           const design::Quantities& quantities);

/// One constraint a design breaks: its value and the bound it passes.
struct Violation {
  Constraint constraint;
  double value = 0.0;  ///< the quantity at the design (SI)
  double limit = 0.0;  ///< the bound it passes (SI)
  bool upper = true;   ///< above a maximum (else below a minimum)
};

/// The constraints `design` breaks beyond the feasibility tolerance, in the spec's order.
std::vector<Violation> violations(const DesignReport& design);

/// "time_constant = 0.0712 s > max 0.03 s (2.37 x the limit)".
std::string violation_text(const Violation& v);

/// The violations as JSON: [{quantity, value, limit, bound ("max" or "min"), unit, text}].
nlohmann::json violations_json(const DesignReport& design);

/// True if `a` is a better design than `b`: feasible before infeasible, then by the objective
/// in the spec's sense.
bool better_design(const DesignReport& a, const DesignReport& b, bool maximise);

}  // namespace rheomag::optimise
