#pragma once
// The [optimise] table of a case file: design variables (case keys with bounds), constraints on
// computed quantities, the objective and the operating point. Format: docs/optimisation.md.

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "case/case_file.hpp"
#include "case/case_key.hpp"
#include "case/case_sections.hpp"
#include "core/enum_names.hpp"
#include "design/quantities.hpp"

namespace rheomag::optimise {

/// [optimise] is a section of case files read by this layer.
inline const bool kOptimiseSectionRegistered = cases::register_case_section("optimise");

/// One design variable: a numeric case key varied between bounds (file units).
struct DesignVariable {
  std::string key;        ///< as written, e.g. "geometry.neck_radius"
  cases::CaseKey target;  ///< the key resolved against the case
  double lower = 0.0, upper = 0.0;
  double initial = 0.0;  ///< the case's value
};

/// One inequality constraint lower <= quantity <= upper (SI units; +-inf when absent).
struct Constraint {
  design::Quantity quantity = design::Quantity::dp_on;
  double lower = -INFINITY, upper = INFINITY;
  std::string where;  ///< "file:line: optimise.constraint[i]" for reports
};

/// One term of the objective: weight x quantity / scale.
struct ObjectiveTerm {
  design::Quantity quantity = design::Quantity::dp_on;
  double weight = 1.0;
  double scale = 1.0;  ///< normaliser; weighted sums: |quantity at the start design|
};

/// The epsilon-constraint sweep of [optimise.pareto]: the objective is optimised while
/// `quantity` (the second objective) is constrained at `points` levels between its extremes.
struct ParetoSpec {
  design::Quantity quantity = design::Quantity::dp_on;
  bool maximise = false;  ///< the second objective's own sense
  int points = 5;         ///< epsilon levels, end points included
};

/// Discrete choices enumerated around the continuous optimisation: a string case key
/// (dotted; "fluid" sets [case] fluid and geometry.fluid_material) and its candidates.
struct DiscreteChoice {
  std::string key;        ///< as written
  cases::CaseKey target;  ///< resolved against the case
  std::vector<std::string> values;
};

/// [optimise] response_model: how each design's response_time is computed.
enum class ResponseModel {
  transient,     ///< two transient runs (design/response_time.hpp)
  quasi_static,  ///< the quasi-static reduction on static solves (transient/quasi_static.hpp)
};

/// Names of ResponseModel in case files.
inline constexpr auto kResponseModelNames = enum_names<ResponseModel>(
    {{ResponseModel::transient, "transient"}, {ResponseModel::quasi_static, "quasi_static"}});

/// [optimise] differences: how the gradients' finite differences are taken.
enum class Differences {
  central,  ///< u +- step: 2n designs per gradient, error O(step^2)
  forward,  ///< u + step (u - step at the upper bound): n designs per gradient, error O(step)
};

/// Names of Differences in case files.
inline constexpr auto kDifferencesNames =
    enum_names<Differences>({{Differences::central, "central"}, {Differences::forward, "forward"}});

/// Everything the optimiser needs from the case.
struct OptimiseSpec {
  std::vector<DesignVariable> variables;
  std::vector<Constraint> constraints;
  std::string objective = "dp_on";   ///< the objective's name: a quantity's, or "weighted_sum"
  std::vector<ObjectiveTerm> terms;  ///< objective = sum of terms (one term: the quantity itself)
  bool maximise = true;
  double current = 1.0;                     ///< on-state coil current [A]
  double flow = 0.0;                        ///< design flow rate [m^3/s] (0: not given)
  double velocity = 0.0;                    ///< damper: design piston velocity [m/s] (0: not given)
  double speed = 0.0;                       ///< brake: design rotor speed [rad/s] (0: not given)
  std::map<std::string, double> densities;  ///< [optimise.density]: material -> [kg/m^3]
  int max_iterations = 40;                  ///< Ipopt iterations
  double tolerance = 1e-4;                  ///< Ipopt relative tolerance on the scaled problem
  double step = 1e-3;  ///< finite-difference step as a fraction of each bound range
  Differences differences = Differences::central;  ///< central or forward differences
  double supply_voltage = 0.0;  ///< driver voltage step for rise_time [V] (0: not given)
  /// How response_time is computed: transient runs, or the quasi-static reduction checked by
  /// transient runs at the optimum (OptimiseResult::response_check).
  ResponseModel response_model = ResponseModel::transient;
  double heat_transfer = 10.0;      ///< coil outer surface to ambient [W/(m^2 K)]
  double thermal_resistance = 0.0;  ///< coil to ambient [K/W]; > 0 overrides heat_transfer
  double duty = 1.0;  ///< fraction of the time at the operating point (coil/fluid_temperature)
  std::optional<ParetoSpec> pareto;
  std::vector<DiscreteChoice> choices;  ///< [optimise] enumerate
};

/// The objective of a design: sum of weight x quantity / scale over the terms. InputError if a
/// quantity is missing or not finite.
double objective_value(const OptimiseSpec& spec, const design::Quantities& q);

/// Every quantity the spec's objective and constraints use (and the Pareto quantity).
std::vector<design::Quantity> used_quantities(const OptimiseSpec& spec);

/// True when the spec uses quantity `q`.
bool uses(const OptimiseSpec& spec, design::Quantity q);

/// The quantity named `name`; InputError naming it, with the closest name and the valid names
/// (`where` prefixes the message), if it is not one.
design::Quantity parse_quantity(const std::string& name, const std::string& where);

/// Reads and checks the [optimise] table of a case: unknown design keys (with the closest key),
/// reversed bounds, initial values outside the bounds, non-positive bounds of lengths and
/// counts, unknown quantities (with the closest name) -> InputError naming file, line and key.
OptimiseSpec read_optimise_spec(const cases::Case& c);

}  // namespace rheomag::optimise
