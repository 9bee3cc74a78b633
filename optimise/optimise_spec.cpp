#include "optimise/optimise_spec.hpp"

#include <cmath>

#include "magnetostatics/toml_section.hpp"
#include "mesh/error.hpp"
#include "optimise/optimise_case_edit.hpp"

namespace rheomag::optimise {

const std::vector<std::pair<std::string, std::string>>& quantity_units() {
  static const std::vector<std::pair<std::string, std::string>> units = {
      {"dp_on", "Pa"},        {"dp_off", "Pa"},
      {"dynamic_range", "-"}, {"b_gap", "T"},
      {"peak_steel_b", "T"},  {"inductance", "H"},
      {"resistance", "Ohm"},  {"time_constant", "s"},
      {"power", "W"},         {"current_density", "A/m^2"},
      {"copper_fill", "-"},   {"outer_radius", "m"},
      {"length", "m"},        {"min_gap", "m"}};
  return units;
}

namespace {

void check_quantity(const magnetostatics::TomlSection& section, std::string_view key,
                    const std::string& name) {
  std::vector<std::string_view> known;
  for (const auto& [q, unit] : quantity_units()) {
    if (q == name) return;
    known.push_back(q);
  }
  const std::string close = magnetostatics::closest_key(name, known);
  section.fail(key, "unknown quantity \"" + name + "\"" +
                        (close.empty() ? "" : " (did you mean \"" + close + "\"?)") +
                        "; known: dp_on, dp_off, dynamic_range, b_gap, peak_steel_b, inductance, "
                        "resistance, time_constant, power, current_density, copper_fill, "
                        "outer_radius, length, min_gap");
}

}  // namespace

OptimiseSpec read_optimise_spec(const magnetostatics::Case& c) {
  const std::string file = c.source.string();
  const magnetostatics::TomlSection top(c.table, "", file);
  auto section = top.table("optimise");
  if (!section)
    throw InputError(file + ": the case has no [optimise] table (docs/optimisation.md)");
  section->allow_only({"objective", "sense", "current", "flow", "max_iterations", "tolerance",
                       "step", "variable", "constraint"});
  OptimiseSpec spec;
  spec.objective = section->string("objective").value_or("dp_on");
  check_quantity(*section, "objective", spec.objective);
  const std::string sense = section->string("sense").value_or("maximise");
  if (sense == "maximise" || sense == "maximize")
    spec.maximise = true;
  else if (sense == "minimise" || sense == "minimize")
    spec.maximise = false;
  else
    section->fail("sense", "expected \"maximise\" or \"minimise\", got \"" + sense + "\"");
  spec.current = section->number_or("current", 1.0);
  spec.flow = section->positive("flow");
  spec.max_iterations = static_cast<int>(section->integer_or("max_iterations", 40));
  if (spec.max_iterations < 1 || spec.max_iterations > 10000)
    section->fail("max_iterations", "expected an integer in 1..10000");
  spec.tolerance = section->positive_or("tolerance", 1e-4);
  spec.step = section->positive_or("step", 1e-3);
  if (spec.step > 0.1) section->fail("step", "expected a fraction of the bound range <= 0.1");

  const auto variables = section->table_array("variable");
  if (variables.empty())
    section->fail("variable", "no design variable: add [[optimise.variable]] key/lower/upper");
  for (const auto& v : variables) {
    v.allow_only({"key", "lower", "upper"});
    DesignVariable variable;
    variable.key = v.required_string("key");
    if (variable.key.rfind("optimise.", 0) == 0 || variable.key.rfind("optimise", 0) == 0)
      v.fail("key", "a design variable cannot be part of [optimise]");
    variable.initial = numeric_case_value(c.table, variable.key, v.where("key"));
    const auto lower = v.number("lower"), upper = v.number("upper");
    if (!lower || !upper) v.fail(lower ? "upper" : "lower", "required (same unit as the key)");
    variable.lower = *lower;
    variable.upper = *upper;
    if (!(variable.lower < variable.upper))
      v.fail("upper", "bounds reversed or empty: lower = " + std::to_string(variable.lower) +
                          " must be < upper = " + std::to_string(variable.upper));
    if (variable.key.rfind("geometry.", 0) == 0 && !(variable.lower > 0.0))
      v.fail("lower",
             "dimensions and turns must stay > 0; got lower = " + std::to_string(variable.lower));
    if (variable.initial < variable.lower || variable.initial > variable.upper)
      v.fail("key", "initial value " + std::to_string(variable.initial) +
                        " is outside the bounds [" + std::to_string(variable.lower) + ", " +
                        std::to_string(variable.upper) + "]");
    for (const auto& other : spec.variables)
      if (other.key == variable.key) v.fail("key", "\"" + variable.key + "\" is listed twice");
    spec.variables.push_back(variable);
  }
  for (const auto& k : section->table_array("constraint")) {
    k.allow_only({"quantity", "min", "max"});
    Constraint constraint;
    constraint.quantity = k.required_string("quantity");
    check_quantity(k, "quantity", constraint.quantity);
    constraint.lower = k.number("min").value_or(-INFINITY);
    constraint.upper = k.number("max").value_or(INFINITY);
    if (std::isinf(constraint.lower) && std::isinf(constraint.upper))
      k.fail("quantity", "a constraint needs min, max or both (SI units)");
    if (!(constraint.lower <= constraint.upper)) k.fail("max", "min > max");
    constraint.where = k.where();
    spec.constraints.push_back(constraint);
  }
  return spec;
}

}  // namespace rheomag::optimise
