// Checked access to TOML tables with file:line:key error messages.

#include "case/toml_section.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace rheomag::cases {

std::string toml_location(const std::string& file, const toml::source_region& where) {
  if (where.begin.line == 0) return file;
  return file + ":" + std::to_string(where.begin.line);
}

std::string format_number(double value) {
  std::ostringstream out;
  out.precision(12);
  out << value;
  return out.str();
}

TomlSection::TomlSection(const toml::table& table, std::string path, std::string file)
    : table_(&table), path_(std::move(path)), file_(std::move(file)) {}

std::string TomlSection::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

std::string TomlSection::where(std::string_view key) const {
  // A value set by a program (a sweep's design edits a copy of the base case) has no source;
  // its key keeps the line it had in the file.
  toml::source_region region = table_->source();
  if (const auto it = table_->find(key); it != table_->end())
    region = it->second.source().begin.line != 0 ? it->second.source() : it->first.source();
  return toml_location(file_, region) + ": " + key_path(key);
}

std::string TomlSection::where() const {
  return toml_location(file_, table_->source()) + ": " + (path_.empty() ? "(top level)" : path_);
}

void TomlSection::fail(std::string_view key, const std::string& message) const {
  throw InputError(where(key) + ": " + message);
}

void TomlSection::allow_only(const std::vector<std::string_view>& known) const {
  for (auto&& [key, value] : *table_) {
    const std::string_view name = key.str();
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    std::string message =
        toml_location(file_, key.source().begin.line ? key.source() : value.source()) +
        ": unknown key '" + key_path(name) + "'";
    const std::string suggestion = closest_key(name, known);
    if (!suggestion.empty())
      message += "; did you mean '" + key_path(suggestion) + "'?";
    else {
      message += "; expected one of:";
      for (std::string_view k : known) message += " " + std::string(k);
    }
    throw InputError(message);
  }
}

void TomlSection::refuse_near_misses(const std::vector<std::string_view>& known) const {
  for (auto&& [key, value] : *table_) {
    const std::string_view name = key.str();
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    for (std::string_view candidate : known)
      if (edit_distance(name, candidate) <= 2)
        throw InputError(
            toml_location(file_, key.source().begin.line ? key.source() : value.source()) +
            ": unknown key '" + key_path(name) + "'; did you mean '" + key_path(candidate) + "'?");
  }
}

bool TomlSection::has(std::string_view key) const {
  return table_->contains(key);
}

const toml::node* TomlSection::node(std::string_view key) const {
  return table_->get(key);
}

std::optional<double> TomlSection::number(std::string_view key) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  double value = 0.0;
  if (auto i = n->value_exact<int64_t>())
    value = static_cast<double>(*i);
  else if (auto f = n->value_exact<double>())
    value = *f;
  else
    fail(key, "expected a number");
  if (!std::isfinite(value)) fail(key, "expected a finite number, got " + format_number(value));
  return value;
}

double TomlSection::number_or(std::string_view key, double fallback) const {
  return number(key).value_or(fallback);
}

std::vector<double> TomlSection::numbers(std::string_view key) const {
  const toml::node* n = node(key);
  if (!n) return {};
  const toml::array* array = n->as_array();
  if (!array) return {*number(key)};
  std::vector<double> out;
  for (const toml::node& item : *array) {
    const std::optional<double> value = item.value<double>();
    if (!value || !std::isfinite(*value))
      fail(key, "expected a number or a list of finite numbers");
    out.push_back(*value);
  }
  return out;
}

double TomlSection::quantity(std::string_view key, const Domain& domain) const {
  const std::optional<double> value = optional_quantity(key, domain);
  if (!value) fail(key, "missing; expected " + domain.describe());
  return *value;
}

std::optional<double> TomlSection::optional_quantity(std::string_view key,
                                                     const Domain& domain) const {
  const std::optional<double> value = number(key);
  if (value && !domain.contains(*value)) fail(key, domain.violation(*value));
  return value;
}

double TomlSection::quantity_or(std::string_view key, const Domain& domain, double fallback) const {
  return optional_quantity(key, domain).value_or(fallback);
}

std::vector<double> TomlSection::quantities(std::string_view key, const Domain& domain) const {
  std::vector<double> result;
  const toml::node* n = node(key);
  if (!n) return result;
  const toml::array* items = n->as_array();
  if (!items) fail(key, "expected a list of numbers");
  for (std::size_t i = 0; i < items->size(); ++i) {
    const toml::node& item = (*items)[i];
    double value = 0.0;
    if (auto iv = item.value_exact<int64_t>())
      value = static_cast<double>(*iv);
    else if (auto fv = item.value_exact<double>())
      value = *fv;
    else
      fail(key, "item " + std::to_string(i + 1) + ": expected a number");
    if (!domain.contains(value))
      fail(key, "item " + std::to_string(i + 1) + ": " + domain.violation(value));
    result.push_back(value);
  }
  return result;
}

std::vector<std::string> TomlSection::strings(std::string_view key) const {
  std::vector<std::string> result;
  const toml::node* n = node(key);
  if (!n) return result;
  const toml::array* items = n->as_array();
  if (!items) fail(key, "expected a list of strings");
  for (std::size_t i = 0; i < items->size(); ++i) {
    auto text = (*items)[i].value_exact<std::string>();
    if (!text) fail(key, "item " + std::to_string(i + 1) + ": expected a string");
    result.push_back(*text);
  }
  return result;
}

double TomlSection::positive(std::string_view key) const {
  return quantity(key, Domain::positive());
}

double TomlSection::positive_or(std::string_view key, double fallback) const {
  return quantity_or(key, Domain::positive(), fallback);
}

double TomlSection::non_negative_or(std::string_view key, double fallback) const {
  return quantity_or(key, Domain::non_negative(), fallback);
}

long long TomlSection::integer_or(std::string_view key, long long fallback) const {
  const toml::node* n = node(key);
  if (!n) return fallback;
  if (auto i = n->value_exact<int64_t>()) return *i;
  fail(key, "expected an integer");
}

std::optional<std::string> TomlSection::string(std::string_view key) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  if (auto s = n->value_exact<std::string>()) return *s;
  fail(key, "expected a string");
}

std::string TomlSection::required_string(std::string_view key) const {
  std::optional<std::string> value = string(key);
  if (!value) fail(key, "missing; expected a string");
  if (value->empty()) fail(key, "expected a non-empty string");
  return *value;
}

bool TomlSection::boolean_or(std::string_view key, bool fallback) const {
  const toml::node* n = node(key);
  if (!n) return fallback;
  if (auto b = n->value_exact<bool>()) return *b;
  fail(key, "expected true or false");
}

std::vector<std::pair<double, double>> TomlSection::pairs(std::string_view key) const {
  std::vector<std::pair<double, double>> result;
  const toml::node* n = node(key);
  if (!n) return result;
  const toml::array* rows = n->as_array();
  if (!rows) fail(key, "expected a list of [x, y] pairs");
  for (std::size_t i = 0; i < rows->size(); ++i) {
    const toml::array* row = (*rows)[i].as_array();
    const std::string item = "item " + std::to_string(i + 1);
    if (!row || row->size() != 2) fail(key, item + ": expected a pair [x, y]");
    double xy[2] = {0.0, 0.0};
    for (std::size_t k = 0; k < 2; ++k) {
      const toml::node& v = (*row)[k];
      if (auto iv = v.value_exact<int64_t>())
        xy[k] = static_cast<double>(*iv);
      else if (auto fv = v.value_exact<double>())
        xy[k] = *fv;
      else
        fail(key, item + ": expected numbers");
      if (!std::isfinite(xy[k])) fail(key, item + ": expected finite numbers");
    }
    result.emplace_back(xy[0], xy[1]);
  }
  return result;
}

std::optional<TomlSection> TomlSection::table(std::string_view key) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const toml::table* t = n->as_table();
  if (!t) fail(key, "expected a table");
  return TomlSection(*t, key_path(key), file_);
}

std::vector<TomlSection> TomlSection::table_array(std::string_view key) const {
  std::vector<TomlSection> result;
  const toml::node* n = node(key);
  if (!n) return result;
  const toml::array* a = n->as_array();
  if (!a) fail(key, "expected an array of tables ([[" + std::string(key) + "]])");
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::table* t = (*a)[i].as_table();
    if (!t) fail(key, "item " + std::to_string(i + 1) + ": expected a table");
    result.emplace_back(*t, key_path(key) + "[" + std::to_string(i + 1) + "]", file_);
  }
  return result;
}

toml::table parse_toml(std::string_view text, const std::string& file) {
  try {
    return toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    const auto& begin = e.source().begin;
    throw InputError(file + ":" + std::to_string(begin.line) + ":" + std::to_string(begin.column) +
                     ": TOML syntax error: " + std::string(e.description()));
  }
}

std::string_view without_byte_order_mark(std::string_view text) {
  constexpr std::string_view bom = "\xEF\xBB\xBF";
  if (text.substr(0, bom.size()) == bom) text.remove_prefix(bom.size());
  return text;
}

toml::table parse_toml_file(const std::string& path) {
  return parse_toml(read_input_file(path), path);
}

}  // namespace rheomag::cases
