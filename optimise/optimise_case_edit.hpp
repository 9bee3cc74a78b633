#pragma once
// Reading and setting numeric keys of a case's TOML table by dotted path ("geometry.turns"),
// including template parameters the file leaves at their defaults.

#include <toml++/toml.h>
#include <string>
#include <vector>

#include "magnetostatics/case_file.hpp"

namespace rheomag::optimise {

/// The number at dotted `key` of a case table, in file units; a parametric-template key absent
/// from the file gives its default. InputError (prefixed by `where`, with the closest existing
/// key) if the key does not exist or is not a number.
double numeric_case_value(const toml::table& table, const std::string& key,
                          const std::string& where);

/// A copy of `table` with each numeric `keys[i]` set to `values[i]` (file units).
toml::table with_values(const toml::table& table, const std::vector<std::string>& keys,
                        const std::vector<double>& values);

/// A copy of `table` with the string at dotted `key` set to `value` ("fluid" sets [case] fluid
/// and geometry.fluid_material together, so the gaps and the fluid model agree).
toml::table with_text(const toml::table& table, const std::string& key, const std::string& value);

/// Parses a case from an edited table (`source` names it in messages and resolves paths).
magnetostatics::Case case_from_table(const toml::table& table, const std::string& source);

/// True if `key` is a count parameter of the case's template (e.g. geometry.turns).
bool is_count_key(const toml::table& table, const std::string& key);

/// The TOML text of a table.
std::string toml_text(const toml::table& table);

}  // namespace rheomag::optimise
