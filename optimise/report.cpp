#include "optimise/report.hpp"

#include <cmath>

#include "optimise/problem.hpp"

namespace rheomag::optimise {

DesignReport report_design(const OptimiseSpec& spec, const std::vector<double>& x,
                           const design::Quantities& quantities) {
  DesignReport report;
  report.x = x;
  report.quantities = quantities;
  report.objective = objective_value(spec, quantities);
  for (const auto& c : spec.constraints) {
    ConstraintStatus status;
    status.constraint = c;
    status.value = quantity_value(quantities, c.quantity);
    const double tolerance = kFeasibilityTolerance * constraint_scale(c);
    status.satisfied = status.value >= c.lower - tolerance && status.value <= c.upper + tolerance;
    const double near = 1e-2 * constraint_scale(c);
    status.active =
        std::abs(status.value - c.lower) <= near || std::abs(status.value - c.upper) <= near;
    report.feasible = report.feasible && status.satisfied;
    report.constraints.push_back(status);
  }
  for (std::size_t i = 0; i < spec.variables.size(); ++i) {
    const auto& v = spec.variables[i];
    const double near = 1e-3 * (v.upper - v.lower);
    if (x[i] <= v.lower + near || x[i] >= v.upper - near)
      report.variables_at_bounds.push_back(v.key);
  }
  return report;
}

bool better_design(const DesignReport& a, const DesignReport& b, bool maximise) {
  if (a.feasible != b.feasible) return a.feasible;
  return maximise ? a.objective > b.objective : a.objective < b.objective;
}

}  // namespace rheomag::optimise
