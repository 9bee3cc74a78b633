#include "optimise/optimise_case_edit.hpp"

#include <cmath>
#include <sstream>

#include "magnetostatics/templates.hpp"
#include "magnetostatics/toml_section.hpp"
#include "mesh/error.hpp"

namespace rheomag::optimise {

namespace {

std::vector<std::string> split_dotted(const std::string& key) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(key);
  while (std::getline(in, part, '.')) parts.push_back(part);
  return parts;
}

// Every numeric leaf key of a table (dotted), for suggestions.
void numeric_keys(const toml::table& table, const std::string& prefix,
                  std::vector<std::string>& out) {
  for (const auto& [k, node] : table) {
    const std::string path =
        prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (node.is_number())
      out.push_back(path);
    else if (const auto* sub = node.as_table())
      numeric_keys(*sub, path, out);
  }
}

// Template parameters (numbers) absent from the file: key -> default in file units.
std::vector<std::pair<std::string, double>> template_defaults(const toml::table& table) {
  std::vector<std::pair<std::string, double>> out;
  const auto name = table["geometry"]["template"].value<std::string>();
  if (!name) return out;
  const auto* valve = magnetostatics::find_template(*name);
  if (!valve) return out;
  const double scale = table["case"]["units"].value_or(std::string("m")) == "mm" ? 1e3 : 1.0;
  for (const auto& p : valve->parameters) {
    if (p.kind == magnetostatics::ParameterKind::length)
      out.emplace_back("geometry." + p.key, p.default_number * scale);
    else if (p.kind == magnetostatics::ParameterKind::count)
      out.emplace_back("geometry." + p.key, p.default_number);
  }
  return out;
}

}  // namespace

double numeric_case_value(const toml::table& table, const std::string& key,
                          const std::string& where) {
  const toml::node* node = &table;
  for (const auto& part : split_dotted(key)) {
    const auto* t = node ? node->as_table() : nullptr;
    node = t ? t->get(part) : nullptr;
  }
  if (node && node->is_number()) return node->value<double>().value();
  if (node) throw InputError(where + ": \"" + key + "\" is not a number in the case");
  const auto defaults = template_defaults(table);
  for (const auto& [k, value] : defaults)
    if (k == key) return value;
  std::vector<std::string> keys;
  numeric_keys(table, "", keys);
  for (const auto& [k, value] : defaults) keys.push_back(k);
  std::vector<std::string_view> views(keys.begin(), keys.end());
  const std::string close = magnetostatics::closest_key(key, views);
  throw InputError(where + ": \"" + key + "\" is not a numeric key of the case" +
                   (close.empty() ? "" : " (did you mean \"" + close + "\"?)"));
}

bool is_count_key(const toml::table& table, const std::string& key) {
  const auto name = table["geometry"]["template"].value<std::string>();
  const auto* valve = name ? magnetostatics::find_template(*name) : nullptr;
  if (!valve) return false;
  for (const auto& p : valve->parameters)
    if (p.kind == magnetostatics::ParameterKind::count && key == "geometry." + p.key) return true;
  return false;
}

namespace {

// The table holding the last part of dotted `key` (created if absent) and that last part.
std::pair<toml::table*, std::string> parent_of(toml::table& root, const std::string& key) {
  const auto parts = split_dotted(key);
  toml::table* t = &root;
  for (std::size_t p = 0; p + 1 < parts.size(); ++p) {
    auto* sub = t->get_as<toml::table>(parts[p]);
    if (!sub) sub = t->insert_or_assign(parts[p], toml::table{}).first->second.as_table();
    t = sub;
  }
  return {t, parts.empty() ? std::string() : parts.back()};
}

}  // namespace

toml::table with_values(const toml::table& table, const std::vector<std::string>& keys,
                        const std::vector<double>& values) {
  toml::table out = table;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    auto [parent, last] = parent_of(out, keys[i]);
    parent->insert_or_assign(last, values[i]);
  }
  return out;
}

toml::table with_text(const toml::table& table, const std::string& key, const std::string& value) {
  toml::table out = table;
  if (key == "fluid") {
    parent_of(out, "case.fluid").first->insert_or_assign("fluid", value);
    if (out["geometry"]["template"])
      parent_of(out, "geometry.x").first->insert_or_assign("fluid_material", value);
    return out;
  }
  auto [parent, last] = parent_of(out, key);
  parent->insert_or_assign(last, value);
  return out;
}

std::string toml_text(const toml::table& table) {
  std::ostringstream out;
  out << table;
  return out.str();
}

magnetostatics::Case case_from_table(const toml::table& table, const std::string& source) {
  return magnetostatics::parse_case(toml_text(table), source);
}

}  // namespace rheomag::optimise
