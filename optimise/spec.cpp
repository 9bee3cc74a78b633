#include "optimise/spec.hpp"
#include "valve/valve_chain.hpp"  // registers [valve]: base cases carry it

#include <algorithm>
#include <cmath>

#include "case/femm_sidecar.hpp"
#include "case/material_library.hpp"
#include "case/toml_section.hpp"
#include "core/error.hpp"

namespace rheomag::optimise {

design::Quantity parse_quantity(const std::string& name, const std::string& where) {
  if (auto q = design::kQuantityNames.find(name)) return *q;
  std::vector<std::string_view> known;
  std::string list;
  for (design::Quantity q : design::all_quantities()) {
    known.push_back(design::kQuantityNames.name(q));
    list += (list.empty() ? "" : ", ") + design::quantity_name(q);
  }
  const std::string close = closest_key(name, known);
  throw InputError(where + ": unknown quantity \"" + name + "\"" +
                   (close.empty() ? "" : " (did you mean \"" + close + "\"?)") +
                   "; known: " + list);
}

double objective_value(const OptimiseSpec& spec, const design::Quantities& q) {
  double sum = 0.0;
  for (const auto& term : spec.terms) {
    if (!q.has(term.quantity))
      throw InputError("optimise: quantity \"" + design::quantity_name(term.quantity) +
                       "\" is not available for this case");
    sum += term.weight * q[term.quantity] / term.scale;
  }
  return sum;
}

std::vector<design::Quantity> used_quantities(const OptimiseSpec& spec) {
  std::vector<design::Quantity> out;
  auto add = [&](design::Quantity q) {
    if (std::find(out.begin(), out.end(), q) == out.end()) out.push_back(q);
  };
  for (const auto& t : spec.terms) add(t.quantity);
  for (const auto& c : spec.constraints) add(c.quantity);
  if (spec.pareto) add(spec.pareto->quantity);
  return out;
}

bool uses(const OptimiseSpec& spec, design::Quantity q) {
  const auto used = used_quantities(spec);
  return std::find(used.begin(), used.end(), q) != used.end();
}

namespace {

design::Quantity read_quantity(const cases::TomlSection& section, std::string_view key,
                               const std::string& name) {
  return parse_quantity(name, section.where(key));
}

bool read_sense(const cases::TomlSection& section) {
  const std::string sense = section.string("sense").value_or("maximise");
  if (sense == "maximise" || sense == "maximize") return true;
  if (sense == "minimise" || sense == "minimize") return false;
  section.fail("sense", "expected \"maximise\" or \"minimise\", got \"" + sense + "\"");
  return true;
}

// objective = "dp_on" or objective = { dp_on = 1.0, power = -0.5 } (weighted sum).
void read_objective(const cases::TomlSection& section, OptimiseSpec& spec) {
  const toml::node* node = section.node("objective");
  if (node && node->is_table()) {
    for (const auto& [name, weight] : *node->as_table()) {
      ObjectiveTerm term;
      term.quantity = read_quantity(section, "objective", std::string(name.str()));
      const auto w = weight.value<double>();
      if (!w || !std::isfinite(*w) || *w == 0.0)
        section.fail("objective",
                     "weight of \"" + std::string(name.str()) + "\" must be a non-zero number");
      term.weight = *w;
      term.scale = 0.0;  // set to |value at the start| by the run
      spec.terms.push_back(term);
    }
    if (spec.terms.empty()) section.fail("objective", "empty weighted sum");
    spec.objective =
        spec.terms.size() == 1 ? design::quantity_name(spec.terms[0].quantity) : "weighted_sum";
    if (spec.terms.size() == 1) spec.terms[0].scale = 1.0, spec.terms[0].weight = 1.0;
    return;
  }
  spec.objective = section.string("objective").value_or("dp_on");
  spec.terms = {ObjectiveTerm{read_quantity(section, "objective", spec.objective), 1.0, 1.0}};
}

void read_pareto(const cases::TomlSection& optimise, OptimiseSpec& spec) {
  auto section = optimise.table("pareto");
  if (!section) return;
  section->allow_only({"quantity", "sense", "points"});
  ParetoSpec pareto;
  pareto.quantity = read_quantity(*section, "quantity", section->required_string("quantity"));
  if (!section->has("sense")) section->fail("sense", "required: \"maximise\" or \"minimise\"");
  pareto.maximise = read_sense(*section);
  pareto.points = static_cast<int>(section->integer_or("points", 5));
  if (pareto.points < 2 || pareto.points > 100)
    section->fail("points", "expected an integer in 2..100 (epsilon levels, end points included)");
  if (spec.terms.size() == 1 && spec.terms[0].quantity == pareto.quantity)
    section->fail("quantity", "the second objective must differ from the objective");
  spec.pareto = pareto;
}

// enumerate = { "geometry.core_material" = ["AISI 1010", "AISI 1018"], fluid = [...] }
void read_choices(const cases::Case& c, const cases::TomlSection& section, OptimiseSpec& spec) {
  const toml::node* node = section.node("enumerate");
  if (!node) return;
  if (!node->is_table())
    section.fail("enumerate", "expected a table of key = [\"choice\", ...] (string case keys)");
  std::size_t combinations = 1;
  for (const auto& [name, values] : *node->as_table()) {
    DiscreteChoice choice;
    choice.key = std::string(name.str());
    const auto* array = values.as_array();
    if (!array || array->empty())
      section.fail("enumerate", "\"" + choice.key + "\": expected a non-empty array of strings");
    for (const auto& v : *array) {
      const auto text = v.value<std::string>();
      if (!text) section.fail("enumerate", "\"" + choice.key + "\": expected strings");
      choice.values.push_back(*text);
    }
    try {
      choice.target = cases::resolve_case_key(c, choice.key, section.where("enumerate"));
    } catch (const InputError&) {
      choice.target.type = cases::KeyType::number;  // reported just below
    }
    if (choice.target.type != cases::KeyType::text)
      section.fail("enumerate", "\"" + choice.key +
                                    "\" is not a string key of the case (e.g. "
                                    "geometry.core_material, or fluid)");
    const bool material = choice.key == "fluid" || choice.key.find("material") != std::string::npos;
    for (const auto& v : choice.values) {  // each candidate must make a valid case
      try {
        if (material) cases::MaterialLibrary::standard().get(v, section.where("enumerate"));
        cases::with(c, {{choice.target, v}});
      } catch (const InputError& e) {
        section.fail("enumerate", "\"" + choice.key + "\" = \"" + v + "\": " + e.what());
      }
    }
    combinations *= choice.values.size();
    spec.choices.push_back(choice);
  }
  if (combinations > 64) section.fail("enumerate", "more than 64 combinations");
}

}  // namespace

OptimiseSpec read_optimise_spec(const cases::Case& c) {
  const std::string file = cases::case_document_source(c);
  const cases::TomlSection top(c.table, "", file);
  auto section = top.table("optimise");
  if (!section)
    throw InputError(file + ": the case has no [optimise] table (docs/optimisation.md)");
  section->allow_only({"objective",      "sense",          "current",        "flow",
                       "max_iterations", "tolerance",      "step",           "variable",
                       "constraint",     "supply_voltage", "heat_transfer",  "thermal_resistance",
                       "duty",           "pareto",         "enumerate",      "velocity",
                       "speed",          "density",        "response_model", "differences"});
  OptimiseSpec spec;
  read_objective(*section, spec);
  spec.maximise = read_sense(*section);
  spec.current = section->quantity_or("current", Domain::finite("A"), 1.0);
  // At 0 A there is no on state and no secant inductance: the coil model failed later with
  // "coil current must be finite and inductance finite", naming no file or key.
  if (spec.current == 0.0)
    section->fail("current", "expected a non-zero on-state coil current (A), got 0");
  spec.flow = section->positive_or("flow", 0.0);
  spec.velocity = section->number_or("velocity", 0.0);
  spec.speed = section->number_or("speed", 0.0);
  if (auto density = section->table("density"))
    for (const auto& [name, node] : density->raw())
      spec.densities[std::string(name.str())] = density->positive(name.str());
  spec.max_iterations = static_cast<int>(section->integer_or("max_iterations", 40));
  if (spec.max_iterations < 1 || spec.max_iterations > 10000)
    section->fail("max_iterations", "expected an integer in 1..10000");
  spec.tolerance = section->positive_or("tolerance", 1e-4);
  spec.step = section->positive_or("step", 1e-3);
  if (spec.step > 0.1) section->fail("step", "expected a fraction of the bound range <= 0.1");
  spec.differences = section->choice_or("differences", kDifferencesNames, Differences::central);
  spec.supply_voltage = section->non_negative_or("supply_voltage", 0.0);
  spec.response_model =
      section->choice_or("response_model", kResponseModelNames, ResponseModel::transient);
  spec.heat_transfer = section->positive_or("heat_transfer", 10.0);
  spec.thermal_resistance = section->non_negative_or("thermal_resistance", 0.0);
  spec.duty = section->quantity_or("duty", Domain::between(0.0, 1.0), 1.0);

  const auto variables = section->table_array("variable");
  if (variables.empty())
    section->fail("variable", "no design variable: add [[optimise.variable]] key/lower/upper");
  for (const auto& v : variables) {
    v.allow_only({"key", "lower", "upper"});
    DesignVariable variable;
    variable.key = v.required_string("key");
    if (variable.key.rfind("optimise.", 0) == 0 || variable.key.rfind("optimise", 0) == 0)
      v.fail("key", "a design variable cannot be part of [optimise]");
    const bool gauge = variable.key == cases::kWireGaugeKey;
    variable.target = cases::resolve_case_key(c, variable.key, v.where("key"), "design variable");
    variable.initial = cases::numeric_case_value(c, variable.target, v.where("key"));
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
    if (gauge && (variable.lower < 0.0 || variable.upper > 40.0))
      v.fail("lower", "wire_gauge bounds must lie in AWG 0..40 (8.3 mm .. 0.080 mm)");
    if (variable.initial < variable.lower || variable.initial > variable.upper)
      v.fail("key", "initial value " + std::to_string(variable.initial) +
                        " is outside the bounds [" + std::to_string(variable.lower) + ", " +
                        std::to_string(variable.upper) + "]");
    for (const auto& other : spec.variables)
      if (other.key == variable.key) v.fail("key", "\"" + variable.key + "\" is listed twice");
    spec.variables.push_back(variable);
  }
  for (const auto& v : spec.variables)
    if (v.key == "geometry.turns")
      for (const auto& w : spec.variables)
        if (w.key == cases::kWireGaugeKey)
          section->fail("variable",
                        "geometry.turns and wire_gauge together: with wire_gauge the "
                        "turns follow from the window, the wire and fill_factor");
  for (const auto& k : section->table_array("constraint")) {
    k.allow_only({"quantity", "min", "max"});
    Constraint constraint;
    constraint.quantity = read_quantity(k, "quantity", k.required_string("quantity"));
    constraint.lower = k.number("min").value_or(-INFINITY);
    constraint.upper = k.number("max").value_or(INFINITY);
    if (std::isinf(constraint.lower) && std::isinf(constraint.upper))
      k.fail("quantity", "a constraint needs min, max or both (SI units)");
    if (!(constraint.lower <= constraint.upper)) k.fail("max", "min > max");
    constraint.where = k.where();
    spec.constraints.push_back(constraint);
  }
  read_pareto(*section, spec);
  read_choices(c, *section, spec);
  // Each device's quantities need its operating point.
  const auto needs = [&](const auto& quantities, bool given, const char* key, const char* what) {
    for (design::Quantity q : quantities)
      if (uses(spec, q) && !given)
        section->fail(key, "\"" + design::quantity_name(q) + "\" needs " + what);
  };
  needs(design::kValveQuantities, spec.flow > 0.0, "flow",
        "the design flow rate: set flow [m^3/s] > 0");
  needs(design::kDamperQuantities, spec.velocity != 0.0, "velocity",
        "the design piston velocity: set velocity [m/s] (not 0)");
  needs(design::kBrakeQuantities, spec.speed != 0.0, "speed",
        "the design rotor speed: set speed [rad/s] (not 0)");
  for (design::Quantity q : {design::Quantity::rise_time, design::Quantity::response_time})
    if (uses(spec, q) && !(spec.supply_voltage > 0.0))
      section->fail("supply_voltage", design::quantity_name(q) +
                                          " needs the driver's voltage step: set supply_voltage "
                                          "[V] > 0");
  return spec;
}

}  // namespace rheomag::optimise
