// Keys are resolved on the case's document (arrays of tables by index) with the template's
// parameter table as a fallback; edits change the typed input and the document together.

#include "case/case_key.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "case/toml_section.hpp"
#include "case/wire_gauge.hpp"
#include "core/error.hpp"
#include "core/format_text.hpp"
#include "core/units.hpp"

namespace rheomag::cases {
namespace {

bool is_index(const std::string& s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

/// The value of an all-digit path component; beyond 10^9 (more items than any list holds) it
/// stops growing, so a 20-digit index is out of range instead of overflowing.
std::size_t index_of(const std::string& s) {
  std::size_t value = 0;
  for (char c : s) {
    if (value > 1'000'000'000) break;
    value = value * 10 + static_cast<std::size_t>(c - '0');
  }
  return value;
}

/// Splits "a.b[2].c" into {"a", "b", "2", "c"}.
std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> parts(1);
  for (char c : key) {
    if (c == '.' || c == '[')
      parts.emplace_back();
    else if (c != ']')
      parts.back() += c;
  }
  return parts;
}

void collect_keys(const toml::node& node, const std::string& prefix,
                  std::vector<std::string>& out) {
  if (const toml::table* t = node.as_table()) {
    for (const auto& [k, v] : *t)
      collect_keys(v, prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str()),
                   out);
  } else if (const toml::array* a = node.as_array()) {
    if (a->empty() || !a->is_array_of_tables()) {
      out.push_back(prefix);  // an array of values is one value (not editable item by item)
      return;
    }
    for (std::size_t i = 0; i < a->size(); ++i)
      collect_keys(*a->get(i), prefix + "." + std::to_string(i), out);
  } else {
    out.push_back(prefix);
  }
}

/// The template parameter named by a "geometry.<key>" path, nullptr if none.
const TemplateParameter* template_parameter(const Case& c, const std::vector<std::string>& path) {
  if (!c.input.valve || path.size() != 2 || path[0] != "geometry") return nullptr;
  for (const TemplateParameter& p : c.input.valve->parameters)
    if (p.key == path[1]) return &p;
  return nullptr;
}

[[noreturn]] void unknown_key(const Case& base, const std::string& key, const std::string& where,
                              const std::string& label, const std::string& why) {
  const std::string suggestion = closest_key(key, value_keys(base));
  std::string message = where + ": " + label + " '" + key + "' " + why;
  if (!suggestion.empty()) message += "; did you mean '" + suggestion + "'?";
  throw InputError(message);
}

/// The document node at a canonical path (nullptr if absent).
const toml::node* node_at(const toml::table& table, const std::vector<std::string>& path) {
  const toml::node* node = &table;
  for (const std::string& part : path) {
    if (!node) return nullptr;
    if (const toml::table* t = node->as_table())
      node = t->get(part);
    else if (const toml::array* a = node->as_array(); a && is_index(part))
      node = a->get(index_of(part));
    else
      return nullptr;
  }
  return node;
}

/// The table holding the last component of `path` (tables created along the way if absent).
toml::table& parent_table(toml::table& root, const std::vector<std::string>& path) {
  toml::node* node = &root;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    if (toml::table* t = node->as_table()) {
      toml::node* next = t->get(path[i]);
      if (!next) next = &t->insert_or_assign(path[i], toml::table{}).first->second;
      node = next;
    } else {
      node = node->as_array()->get(index_of(path[i]));
    }
  }
  return *node->as_table();
}

void set_document_value(toml::table& root, const std::vector<std::string>& path,
                        const KeyValue& value) {
  toml::table& parent = parent_table(root, path);
  std::visit([&](const auto& v) { parent.insert_or_assign(path.back(), v); }, value);
}

double as_number(const KeyValue& value, const std::string& written) {
  if (const double* d = std::get_if<double>(&value)) return *d;
  if (const long long* i = std::get_if<long long>(&value)) return static_cast<double>(*i);
  throw InputError("key '" + written + "': expected a number, got " + format_value(value));
}

const std::string& as_text(const KeyValue& value, const std::string& written) {
  if (const std::string* s = std::get_if<std::string>(&value)) return *s;
  throw InputError("key '" + written + "': expected a name, got " + format_value(value));
}

KeyType type_of(const toml::node& node) {
  if (node.is_integer()) return KeyType::integer;
  if (node.is_floating_point()) return KeyType::number;
  if (node.is_boolean()) return KeyType::boolean;
  return KeyType::text;
}

/// The key of a .fem model's circuit current: "circuit.N.current", or "circuit.current" when
/// the model has one circuit. A .fem has no circuit document, so the path is resolved against
/// the model's circuits.
CaseKey femm_circuit_key(const Case& base, const std::vector<std::string>& parts,
                         const std::string& key, const std::string& where,
                         const std::string& label) {
  const std::size_t n = base.problem.circuits.size();
  std::size_t index = 0;
  if (parts.size() == 3 && is_index(parts[1]) && parts[2] == "current") {
    index = index_of(parts[1]);
    if (index >= n)
      unknown_key(base, key, where, label,
                  "indexes circuit " + parts[1] + " of a model with " + std::to_string(n));
  } else if (!(parts.size() == 2 && parts[1] == "current" && n == 1)) {
    unknown_key(base, key, where, label,
                "is not a circuit current of the .fem model (it has " + std::to_string(n) +
                    " circuit(s); only their currents are design keys)");
  }
  CaseKey resolved;
  resolved.written = key;
  resolved.path = {"circuit", std::to_string(index), "current"};
  resolved.target = KeyTarget::circuit_current;
  resolved.circuit = static_cast<int>(index);
  return resolved;
}

/// A .fem model with its MR fluid changed to `name` of `library`: every block of the old fluid
/// (the gaps and any other fluid block) takes the new fluid's magnetic properties.
void change_femm_fluid(Case& c, const std::string& name, const std::string& written) {
  const MaterialLibrary& library = c.input.library ? *c.input.library : MaterialLibrary::standard();
  if (c.fluid.empty())
    throw InputError("key '" + written + "': " + c.source.string() +
                     " has no fluid gaps (no sidecar .toml with a [fem] table beside it)");
  const LibraryMaterial& m = library.get(name, "key '" + written + "'");
  if (!m.rheology)
    throw InputError("key '" + written + "': '" + name + "' is not an MR fluid of the library");
  const std::string old = normalised_material_name(c.fluid);
  for (Material& material : c.problem.materials)
    if (!old.empty() && normalised_material_name(material.name) == old) material = m.magnetic;
  c.fluid = m.magnetic.name;
  c.input.fluid = name;
}

/// The one solver key of a .fem model, "solver.order": its mesh sizes and boundaries are
/// FEMM's own (block labels, boundary properties), so nothing else of [solver] applies.
CaseKey femm_solver_key(const Case& base, const std::vector<std::string>& parts,
                        const std::string& key, const std::string& where,
                        const std::string& label) {
  if (!(parts.size() == 2 && parts[1] == "order"))
    unknown_key(base, key, where, label,
                "is not a solver key of a .fem model: it takes 'solver.order' (1 or 2) only; "
                "its mesh sizes and boundaries are FEMM's own (block labels, boundary "
                "properties)");
  CaseKey resolved;
  resolved.written = key;
  resolved.path = {"solver", "order"};
  resolved.target = KeyTarget::element_order;
  return resolved;
}

/// The element order of `value` for key `written`: 1 or 2, else InputError.
int element_order(const KeyValue& value, const std::string& written) {
  const double n = as_number(value, written);
  if (n != 1.0 && n != 2.0)
    throw InputError("key '" + written + "': expected 1 or 2 (P1 or P2 triangles), got " +
                     format_text("%g", n));
  return static_cast<int>(n);
}

}  // namespace

std::vector<std::string> value_keys(const Case& c) {
  std::vector<std::string> keys;
  collect_keys(c.table, "", keys);
  if (c.femm) {
    std::erase_if(keys, [](const std::string& k) { return k.rfind("fem.", 0) == 0; });
    for (std::size_t i = 0; i < c.problem.circuits.size(); ++i)
      keys.push_back(c.problem.circuits.size() == 1 ? "circuit.current"
                                                    : "circuit." + std::to_string(i) + ".current");
    keys.push_back("solver.order");
  }
  if (c.input.valve)
    for (const TemplateParameter& p : c.input.valve->parameters)
      keys.push_back("geometry." + p.key);
  // Arrays holding one table may be addressed without the index: offer that form as well.
  std::vector<std::string> short_forms;
  for (const std::string& k : keys) {
    std::string shortened;
    const toml::node* node = &c.table;
    for (const std::string& p : split_key(k)) {
      const toml::array* a = node ? node->as_array() : nullptr;
      if (a && a->size() == 1 && is_index(p)) {
        node = a->get(0);
        continue;
      }
      node = node && node->as_table() ? node->as_table()->get(p)
             : (a && is_index(p))     ? a->get(index_of(p))
                                      : nullptr;
      if (!shortened.empty()) shortened += '.';
      shortened += p;
    }
    if (shortened != k) short_forms.push_back(shortened);
  }
  keys.insert(keys.end(), short_forms.begin(), short_forms.end());
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

CaseKey resolve_case_key(const Case& base, const std::string& key, const std::string& where,
                         const std::string& label) {
  CaseKey resolved;
  resolved.written = key;
  if (key == kWireGaugeKey) {
    if (base.input.winding.fill_factor <= 0.0)
      throw InputError(where + ": \"" + key +
                       "\" as a design variable needs the coil wound from its wire: "
                       "[geometry] wire = \"AWG 24\" and fill_factor = 0.55 instead of turns "
                       "(docs/case-format.md)");
    resolved.path = {"geometry", "wire"};
    resolved.target = KeyTarget::wire_gauge;
    return resolved;
  }
  if (key == "fluid") {
    resolved.path = {"case", "fluid"};
    resolved.type = KeyType::text;
    resolved.target = KeyTarget::fluid;
    return resolved;
  }
  const std::vector<std::string> parts = split_key(key);
  if (std::any_of(parts.begin(), parts.end(), [](const std::string& p) { return p.empty(); }))
    throw InputError(where + ": " + label + " '" + key +
                     "' has an empty component; expected a dotted path like 'geometry.gap_width'");
  if (base.femm && parts.front() == "geometry")
    throw InputError(where + ": " + label + " '" + key + "' cannot be applied to " +
                     base.source.string() +
                     ": a .fem model has no named dimensions (its geometry is FEMM's points, "
                     "segments and arcs); edit the geometry in FEMM, or vary a TOML case's "
                     "[geometry] template parameters");
  if (base.femm && parts.front() == "fem")
    throw InputError(where + ": " + label + " '" + key +
                     "' is part of the [fem] gap list of the .fem's sidecar; which blocks are "
                     "gaps is not a design value");
  if (base.femm && parts.front() == "circuit")
    return femm_circuit_key(base, parts, key, where, label);
  if (base.femm && parts.front() == "solver")
    return femm_solver_key(base, parts, key, where, label);
  const toml::node* node = &base.table;
  for (std::size_t i = 0; i < parts.size();) {
    if (const toml::table* t = node->as_table()) {
      node = t->get(parts[i]);
      resolved.path.push_back(parts[i]);
      ++i;
      if (!node) {
        if (const TemplateParameter* p = template_parameter(base, resolved.path);
            p && i == parts.size()) {
          resolved.target = KeyTarget::template_parameter;
          resolved.parameter = p->key;
          resolved.kind = p->kind;
          if (p->kind == ParameterKind::length) resolved.si_per_unit = base.input.length_unit;
          resolved.type = p->kind == ParameterKind::length || p->kind == ParameterKind::count
                              ? KeyType::number
                              : KeyType::text;
          return resolved;
        }
        unknown_key(base, key, where, label, "does not exist in the case");
      }
    } else if (const toml::array* a = node->as_array()) {
      if (!a->is_array_of_tables() || a->empty())
        unknown_key(base, key, where, label,
                    "goes into a list of values, which is edited as one value");
      if (parts[i].front() == '-' && is_index(parts[i].substr(1)))
        unknown_key(base, key, where, label,
                    "has the negative index " + parts[i] + "; expected an index from 0 to " +
                        std::to_string(a->size() - 1));
      if (is_index(parts[i])) {
        const std::size_t index = index_of(parts[i]);
        if (index >= a->size())
          unknown_key(base, key, where, label,
                      "indexes item " + parts[i] + " of a list of " + std::to_string(a->size()));
        node = a->get(index);
        resolved.path.push_back(parts[i]);
        ++i;
      } else if (a->size() == 1) {
        node = a->get(0);
        resolved.path.push_back("0");
      } else {
        unknown_key(base, key, where, label,
                    "needs an index: the case has " + std::to_string(a->size()) +
                        " entries there (write e.g. '" + resolved.path.front() + ".0." + parts[i] +
                        "')");
      }
    } else {
      unknown_key(base, key, where, label, "goes below a value");
    }
  }
  if (node->is_table() || (node->is_array() && node->as_array()->is_array_of_tables()))
    unknown_key(base, key, where, label, "is a table, not a value");
  if (!node->is_value() || node->is_date() || node->is_time() || node->is_date_time())
    throw InputError(where + ": " + label + " '" + key +
                     "' holds a list, date or time in the case; only numbers, integers, "
                     "booleans and strings can be edited");
  resolved.type = type_of(*node);
  if (const TemplateParameter* p = template_parameter(base, resolved.path)) {
    resolved.target = KeyTarget::template_parameter;
    resolved.parameter = p->key;
    resolved.kind = p->kind;
    if (p->kind == ParameterKind::length) resolved.si_per_unit = base.input.length_unit;
  } else if (resolved.path.size() == 3 && resolved.path[0] == "circuit" &&
             resolved.path[2] == "current") {
    resolved.target = KeyTarget::circuit_current;
    resolved.circuit = std::stoi(resolved.path[1]);
  }
  return resolved;
}

KeyValue case_value(const Case& c, const CaseKey& key) {
  if (key.target == KeyTarget::wire_gauge) {
    const double n = awg_number(c.input.winding.wire_diameter);
    return std::abs(n - std::round(n)) < 1e-6 ? std::round(n) : n;
  }
  if (key.target == KeyTarget::fluid) return c.fluid;
  if (key.target == KeyTarget::circuit_current && c.femm)
    return c.problem.circuits.at(static_cast<std::size_t>(key.circuit)).current;
  if (key.target == KeyTarget::element_order) return static_cast<long long>(c.problem.order);
  if (const toml::node* node = node_at(c.table, key.path)) {
    if (auto i = node->value_exact<int64_t>()) return static_cast<long long>(*i);
    if (auto d = node->value_exact<double>()) return *d;
    if (auto b = node->value_exact<bool>()) return *b;
    if (auto s = node->value_exact<std::string>()) return *s;
  }
  if (key.target == KeyTarget::template_parameter) {
    if (key.kind == ParameterKind::length)
      return c.input.template_values.numbers.at(key.parameter) / key.si_per_unit;
    if (key.kind == ParameterKind::count) return c.input.template_values.numbers.at(key.parameter);
    return c.input.template_values.texts.at(key.parameter);
  }
  throw InputError(c.source.string() + ": key '" + key.written + "' is not in the case");
}

double numeric_case_value(const Case& c, const CaseKey& key, const std::string& where) {
  const KeyValue value = case_value(c, key);
  if (const double* d = std::get_if<double>(&value)) return *d;
  if (const long long* i = std::get_if<long long>(&value)) return static_cast<double>(*i);
  throw InputError(where + ": \"" + key.written + "\" is not a number in the case");
}

bool only_currents(const std::vector<CaseEdit>& edits) {
  return std::all_of(edits.begin(), edits.end(),
                     [](const CaseEdit& e) { return e.key.target == KeyTarget::circuit_current; });
}

Case with(const Case& base, const std::vector<CaseEdit>& edits) {
  Case c = base;
  bool reread = false;
  for (const CaseEdit& edit : edits) {
    const CaseKey& key = edit.key;
    switch (key.target) {
      case KeyTarget::template_parameter:
        if (key.kind == ParameterKind::length)
          c.input.template_values.numbers[key.parameter] =
              as_number(edit.value, key.written) * key.si_per_unit;
        else if (key.kind == ParameterKind::count)
          c.input.template_values.numbers[key.parameter] = as_number(edit.value, key.written);
        else
          c.input.template_values.texts[key.parameter] = as_text(edit.value, key.written);
        set_document_value(c.table, key.path, edit.value);
        break;
      case KeyTarget::circuit_current:
        c.problem.circuits.at(static_cast<std::size_t>(key.circuit)).current =
            as_number(edit.value, key.written);
        if (!c.femm) set_document_value(c.table, key.path, edit.value);
        break;
      case KeyTarget::wire_gauge: {
        const double n = as_number(edit.value, key.written);
        const double whole = std::round(n);
        c.input.winding.wire = wire_text(n);
        c.input.winding.wire_diameter = std::abs(n - whole) < 1e-9
                                            ? awg_diameter(static_cast<int>(whole))
                                            : awg_diameter_relaxed(n);
        set_document_value(c.table, key.path, c.input.winding.wire);
        break;
      }
      case KeyTarget::fluid: {
        const std::string& name = as_text(edit.value, key.written);
        if (c.femm) {
          change_femm_fluid(c, name, key.written);
          break;
        }
        c.input.fluid = name;
        set_document_value(c.table, {"case", "fluid"}, name);
        if (c.input.valve) {
          c.input.template_values.texts["fluid_material"] = name;
          set_document_value(c.table, {"geometry", "fluid_material"}, name);
        }
        break;
      }
      case KeyTarget::element_order:
        c.problem.order = element_order(edit.value, key.written);
        break;
      case KeyTarget::document:
        set_document_value(c.table, key.path, edit.value);
        reread = !c.femm;  // a .fem's document is its sidecar: only later layers read it
        break;
    }
  }
  if (c.femm) return c;
  if (reread) return parse_case(std::move(c.table), c.source.string(), *base.input.library);
  if (!only_currents(edits)) build_case(c);
  return c;
}

std::string format_value(const KeyValue& value) {
  struct Formatter {
    std::string operator()(long long v) const { return std::to_string(v); }
    std::string operator()(double v) const {
      char buffer[40];
      std::snprintf(buffer, sizeof buffer, "%.12g", v);
      return buffer;
    }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(const std::string& v) const { return v; }
  };
  return std::visit(Formatter{}, value);
}

std::string wire_text(double n) {
  const double whole = std::round(n);
  if (std::abs(n - whole) < 1e-9) {
    if (whole >= 1.0) return "AWG " + std::to_string(static_cast<int>(whole));
    return "AWG " + std::string(static_cast<std::size_t>(1.0 - whole), '0');
  }
  char text[48];
  std::snprintf(text, sizeof text, "%.9g mm", awg_diameter_relaxed(n) * 1e3);
  return text;
}

CaseEdit parse_setting(const Case& base, const std::string& setting, const std::string& option) {
  const std::size_t eq = setting.find('=');
  const std::string where = option + " " + setting;
  if (eq == std::string::npos || eq == 0)
    throw InputError(where + ": expected KEY=VALUE, e.g. " + option + " geometry.gap_width=1.2");
  const std::string key_text = setting.substr(0, eq);
  const std::string text = setting.substr(eq + 1);
  const CaseKey key = resolve_case_key(base, key_text, option);
  if (text.empty()) throw InputError(where + ": expected a value after '='");
  auto number = [&]() -> double {
    // A length parameter and a circuit current may carry a unit; the value is in file units.
    if (key.target == KeyTarget::template_parameter && key.kind == ParameterKind::length)
      return parse_quantity(text, QuantityKind::length, where) / key.si_per_unit;
    if (key.target == KeyTarget::circuit_current)
      return parse_quantity(text, QuantityKind::current, where);
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || !std::isfinite(v))
      throw InputError(where + ": '" + key_text + "' holds a number; got \"" + text + "\"");
    return v;
  };
  switch (key.type) {
    case KeyType::integer: {
      const double v = number();
      if (std::trunc(v) != v || std::fabs(v) > 9.0e15)
        throw InputError(where + ": '" + key_text + "' holds an integer; got \"" + text + "\"");
      return {key, static_cast<long long>(v)};
    }
    case KeyType::number:
      return {key, number()};
    case KeyType::boolean:
      if (text == "true") return {key, true};
      if (text == "false") return {key, false};
      throw InputError(where + ": '" + key_text + "' holds true or false; got \"" + text + "\"");
    case KeyType::text:
      return {key, text};
  }
  throw InputError(where + ": unsupported value");
}

Case with_settings(const Case& base, const std::vector<std::string>& settings,
                   const std::string& option) {
  if (settings.empty()) return base;
  std::vector<CaseEdit> edits;
  std::string listed;
  for (const std::string& s : settings) {
    edits.push_back(parse_setting(base, s, option));
    const CaseKey& key = edits.back().key;
    // The unit of the value as the case holds it (a template length in the file's unit).
    const std::string unit =
        key.target == KeyTarget::template_parameter && key.kind == ParameterKind::length
            ? (key.si_per_unit == 1.0    ? " m"
               : key.si_per_unit == 1e-3 ? " mm"
                                         : "")
        : key.target == KeyTarget::circuit_current ? " A"
                                                   : "";
    listed += (listed.empty() ? "" : ", ") + key.written + " = " +
              format_value(edits.back().value) + unit;
  }
  Case edited = with(base, edits);
  // The file's description speaks of the unedited design (its turns, its gap): name the edits.
  edited.description =
      "edited with " + option + ": " + listed +
      (base.description.empty() ? std::string() : " (the file's description no longer holds)");
  return edited;
}

}  // namespace rheomag::cases
