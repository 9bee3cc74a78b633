#pragma once
// Enum <-> name tables: one table per enum gives its text form for files and messages and
// reads it back with a message listing the accepted names.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "core/error.hpp"

namespace rheomag {

/// A fixed table of (value, name) pairs for one enum.
template <typename Enum, std::size_t N>
struct EnumNames {
  std::array<std::pair<Enum, std::string_view>, N> entries;

  /// The name of `value` ("?" for a value missing from the table).
  constexpr std::string_view name(Enum value) const {
    for (const auto& [v, n] : entries)
      if (v == value) return n;
    return "?";
  }
  /// The value named `text`, or nothing.
  constexpr std::optional<Enum> find(std::string_view text) const {
    for (const auto& [v, n] : entries)
      if (n == text) return v;
    return std::nullopt;
  }
  /// The accepted names as "\"a\", \"b\" or \"c\"" (for messages).
  std::string choices() const {
    std::string out;
    for (std::size_t i = 0; i < N; ++i) {
      if (i > 0) out += i + 1 == N ? " or " : ", ";
      out += "\"" + std::string(entries[i].second) + "\"";
    }
    return out;
  }
  /// The value named `text`; InputError "<where>: expected <choices>, got "<text>"" otherwise.
  Enum parse(std::string_view text, const std::string& where) const {
    if (auto value = find(text)) return *value;
    throw InputError(where + ": expected " + choices() + ", got \"" + std::string(text) + "\"");
  }
};

/// Deduces N: `constexpr auto names = enum_names<Kind>({{{Kind::a, "a"}, {Kind::b, "b"}}});`.
template <typename Enum, std::size_t N>
constexpr EnumNames<Enum, N> enum_names(const std::pair<Enum, std::string_view> (&entries)[N]) {
  EnumNames<Enum, N> table{};
  for (std::size_t i = 0; i < N; ++i) table.entries[i] = entries[i];
  return table;
}

}  // namespace rheomag
