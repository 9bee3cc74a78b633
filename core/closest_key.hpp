#pragma once
// Suggestions for misspelt names: the known name closest to what was written.

#include <string>
#include <string_view>
#include <vector>

namespace rheomag {

/// Levenshtein edit distance between two strings (case-insensitive).
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The known name closest to `key` by edit distance, "" when none is within
/// max(3, |key| / 2) edits (a suggestion further away would mislead more than help).
std::string closest_key(std::string_view key, const std::vector<std::string_view>& known);

/// The same for a list of strings.
std::string closest_key(std::string_view key, const std::vector<std::string>& known);

}  // namespace rheomag
