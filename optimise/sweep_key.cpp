#include "optimise/sweep_key.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "magnetostatics/toml_section.hpp"
#include "mesh/error.hpp"

namespace rheomag::optimise {

namespace {

bool is_index(const std::string& s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

/// Splits "a.b[2].c" into {"a", "b", "2", "c"}.
std::vector<std::string> split_key(const std::string& key) {
  std::string normal;
  for (char c : key) {
    if (c == '[') {
      normal += '.';
    } else if (c != ']') {
      normal += c;
    }
  }
  std::vector<std::string> parts;
  std::string part;
  for (char c : normal) {
    if (c == '.') {
      parts.push_back(part);
      part.clear();
    } else {
      part += c;
    }
  }
  parts.push_back(part);
  return parts;
}

void collect_keys(const toml::node& node, const std::string& prefix,
                  std::vector<std::string>& out) {
  if (const toml::table* t = node.as_table()) {
    for (const auto& [k, v] : *t) {
      collect_keys(v, prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str()),
                   out);
    }
  } else if (const toml::array* a = node.as_array()) {
    const bool tables = !a->empty() && a->is_array_of_tables();
    if (!tables) {
      out.push_back(prefix);  // an array of values is one value (not sweepable item by item)
      return;
    }
    for (std::size_t i = 0; i < a->size(); ++i) {
      collect_keys(*a->get(i), prefix + "." + std::to_string(i), out);
    }
  } else {
    out.push_back(prefix);
  }
}

[[noreturn]] void unknown_key(const toml::table& base, const std::string& key,
                              const std::string& where, const std::string& why) {
  const std::string suggestion = closest_key(key, value_keys(base));
  std::string message = where + ": sweep key '" + key + "' " + why;
  if (!suggestion.empty()) message += "; did you mean '" + suggestion + "'?";
  throw InputError(message);
}

}  // namespace

std::string closest_key(const std::string& key, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::string::npos;
  for (const std::string& c : candidates) {
    const std::size_t d = magnetostatics::edit_distance(key, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

std::vector<std::string> value_keys(const toml::table& table) {
  std::vector<std::string> keys;
  collect_keys(table, "", keys);
  // Arrays holding one table may be addressed without the index: offer that form as well.
  std::vector<std::string> short_forms;
  for (const std::string& k : keys) {
    const std::vector<std::string> parts = split_key(k);
    std::string shortened;
    const toml::node* node = &table;
    for (const std::string& p : parts) {
      const toml::array* a = node ? node->as_array() : nullptr;
      if (a && a->size() == 1 && is_index(p)) {
        node = a->get(0);
        continue;
      }
      node = node && node->as_table() ? node->as_table()->get(p)
             : (a && is_index(p))     ? a->get(std::stoul(p))
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

ResolvedKey resolve_key(const toml::table& base, const std::string& key, const std::string& where) {
  ResolvedKey resolved;
  resolved.written = key;
  const std::vector<std::string> parts = split_key(key);
  if (std::any_of(parts.begin(), parts.end(), [](const std::string& p) { return p.empty(); })) {
    throw InputError(where + ": sweep key '" + key +
                     "' has an empty component; expected a dotted path like 'geometry.gap_width'");
  }
  const toml::node* node = &base;
  std::size_t i = 0;
  while (i < parts.size()) {
    if (const toml::table* t = node->as_table()) {
      node = t->get(parts[i]);
      if (!node) unknown_key(base, key, where, "does not exist in the base case");
      resolved.path.push_back(parts[i]);
      ++i;
    } else if (const toml::array* a = node->as_array()) {
      if (!a->is_array_of_tables() || a->empty()) {
        unknown_key(base, key, where, "goes into a list of values, which is swept as one value");
      }
      if (is_index(parts[i])) {
        const std::size_t index = std::stoul(parts[i]);
        if (index >= a->size()) {
          unknown_key(base, key, where,
                      "indexes item " + parts[i] + " of a list of " + std::to_string(a->size()));
        }
        node = a->get(index);
        resolved.path.push_back(parts[i]);
        ++i;
      } else if (a->size() == 1) {
        node = a->get(0);
        resolved.path.push_back("0");
      } else {
        unknown_key(base, key, where,
                    "needs an index: the base case has " + std::to_string(a->size()) +
                        " entries there (write e.g. '" + resolved.path.front() + ".0." + parts[i] +
                        "')");
      }
    } else {
      unknown_key(base, key, where, "goes below a value");
    }
  }
  if (node->is_table() || (node->is_array() && node->as_array()->is_array_of_tables())) {
    unknown_key(base, key, where, "is a table, not a value");
  }
  if (node->is_integer()) {
    resolved.type = KeyType::integer;
  } else if (node->is_floating_point()) {
    resolved.type = KeyType::number;
  } else if (node->is_boolean()) {
    resolved.type = KeyType::boolean;
  } else if (node->is_string()) {
    resolved.type = KeyType::text;
  } else {
    throw InputError(where + ": sweep key '" + key +
                     "' holds a list, date or time in the base case; only numbers, integers, "
                     "booleans and strings can be swept");
  }
  return resolved;
}

void override_key(toml::table& table, const ResolvedKey& key, const KeyValue& value) {
  toml::node* parent = &table;
  for (std::size_t i = 0; i + 1 < key.path.size(); ++i) {
    parent = parent->is_table() ? parent->as_table()->get(key.path[i])
                                : parent->as_array()->get(std::stoul(key.path[i]));
  }
  toml::table* t = parent->as_table();  // the last component always names a table entry
  const std::string& last = key.path.back();
  std::visit([&](const auto& v) { t->insert_or_assign(last, v); }, value);
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

}  // namespace rheomag::optimise
