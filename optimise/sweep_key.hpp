#pragma once
// Dotted key paths into a case file's TOML table ("geometry.gap_width", "circuit.0.current"):
// resolving them, overriding their value, and suggesting the closest key when one is unknown.

#include <toml++/toml.h>
#include <string>
#include <variant>
#include <vector>

namespace rheomag::optimise {

/// A value a sweep gives to a case key.
using KeyValue = std::variant<long long, double, bool, std::string>;

/// TOML type of the value a key holds in the base case.
enum class KeyType { integer, number, boolean, text };

/// A key resolved against the base case: canonical path components (array indices explicit).
struct ResolvedKey {
  std::string written;             ///< as the user wrote it
  std::vector<std::string> path;   ///< canonical components, e.g. {"circuit", "0", "current"}
  KeyType type = KeyType::number;  ///< type of the base value (overrides keep it)
};

/// Resolves `key` (components separated by '.', array index as ".N" or "[N]"; the index of an
/// array holding exactly one table may be left out) in `base`. Throws InputError naming
/// `where` and the key, with the closest existing key (edit distance), when it does not exist
/// or is not a single value.
ResolvedKey resolve_key(const toml::table& base, const std::string& key, const std::string& where);

/// Every value key of `table` in canonical dotted form ("circuit.0.current"), sorted.
std::vector<std::string> value_keys(const toml::table& table);

/// The candidate closest to `key` by case-insensitive Levenshtein distance ("" if none).
std::string closest_key(const std::string& key, const std::vector<std::string>& candidates);

/// Sets the value at `key` (resolved against a table of the same shape) to `value`.
void override_key(toml::table& table, const ResolvedKey& key, const KeyValue& value);

/// The value as written in a CSV cell and in messages (real numbers with 12 significant digits).
std::string format_value(const KeyValue& value);

}  // namespace rheomag::optimise
