#include "optimise/report.hpp"

#include <cmath>
#include <cstdio>

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

std::vector<Violation> violations(const DesignReport& design) {
  std::vector<Violation> out;
  for (const auto& s : design.constraints) {
    if (s.satisfied) continue;
    const bool upper = std::isfinite(s.constraint.upper) && s.value > s.constraint.upper;
    out.push_back({s.constraint, s.value, upper ? s.constraint.upper : s.constraint.lower, upper});
  }
  return out;
}

std::string violation_text(const Violation& v) {
  const std::string unit(design::quantity_unit(v.constraint.quantity));
  const std::string u = unit.empty() ? "" : " " + unit;
  char text[240];
  std::snprintf(text, sizeof text, "%s = %.4g%s %s %.4g%s",
                design::quantity_name(v.constraint.quantity).c_str(), v.value, u.c_str(),
                v.upper ? "> max" : "< min", v.limit, u.c_str());
  std::string out = text;
  if (v.limit != 0.0 && v.value / v.limit > 0.0) {
    std::snprintf(text, sizeof text, " (%.3g x the limit)", v.value / v.limit);
    out += text;
  }
  return out;
}

nlohmann::json violations_json(const DesignReport& design) {
  nlohmann::json out = nlohmann::json::array();
  for (const Violation& v : violations(design))
    out.push_back({{"quantity", design::quantity_name(v.constraint.quantity)},
                   {"value", v.value},
                   {"limit", v.limit},
                   {"bound", v.upper ? "max" : "min"},
                   {"unit", std::string(design::quantity_unit(v.constraint.quantity))},
                   {"text", violation_text(v)}});
  return out;
}

bool better_design(const DesignReport& a, const DesignReport& b, bool maximise) {
  if (a.feasible != b.feasible) return a.feasible;
  return maximise ? a.objective > b.objective : a.objective < b.objective;
}

}  // namespace rheomag::optimise
