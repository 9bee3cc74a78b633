#pragma once
// Checked access to one table of a TOML input file: every key known, every number finite,
// every error naming the file, line and key (shared by the case, material and later readers).

#include <toml++/toml.h>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/closest_key.hpp"
#include "core/enum_names.hpp"
#include "core/input_file.hpp"
#include "core/quantity_domain.hpp"

namespace rheomag::cases {

/// "file:line" for a toml++ source region (just "file" when the line is unknown).
std::string toml_location(const std::string& file, const toml::source_region& where);

/// One table of a TOML file with its dotted path (e.g. "region[2]") for error messages.
class TomlSection {
 public:
  /// Wraps `table` (which must outlive this object); `path` is "" for the root table.
  TomlSection(const toml::table& table, std::string path, std::string file);

  /// Throws InputError naming the first key not in `known` and the closest known key.
  void allow_only(const std::vector<std::string_view>& known) const;
  /// For formats open to extension: keys not in `known` are allowed, but one within two edits of
  /// a known key is refused as a likely misspelling (InputError with the known key).
  void refuse_near_misses(const std::vector<std::string_view>& known) const;

  /// True if the key is present.
  bool has(std::string_view key) const;

  /// A finite number (integer or float) or nothing when absent; InputError if not a number.
  std::optional<double> number(std::string_view key) const;
  /// A finite number, `fallback` when absent.
  double number_or(std::string_view key, double fallback) const;
  /// A finite number or a list of finite numbers (`key = 1.0` or `key = [1.0, 2.0]`), empty
  /// when absent; InputError otherwise.
  std::vector<double> numbers(std::string_view key) const;
  /// A finite number > 0 (required); InputError otherwise.
  double positive(std::string_view key) const;
  /// A finite number > 0, `fallback` when absent.
  double positive_or(std::string_view key, double fallback) const;
  /// A finite number >= 0, `fallback` when absent.
  double non_negative_or(std::string_view key, double fallback) const;
  /// A number in its declared domain (required): InputError "file:line: key: expected <domain>,
  /// got <value>" otherwise. Every physical quantity of an input is read through these.
  double quantity(std::string_view key, const Domain& domain) const;
  /// A number in `domain`, or nothing when absent.
  std::optional<double> optional_quantity(std::string_view key, const Domain& domain) const;
  /// A number in `domain`, `fallback` when absent.
  double quantity_or(std::string_view key, const Domain& domain, double fallback) const;
  /// A list of numbers, each in `domain` (empty when absent).
  std::vector<double> quantities(std::string_view key, const Domain& domain) const;
  /// A list of strings (empty when absent).
  std::vector<std::string> strings(std::string_view key) const;
  /// An integer, `fallback` when absent.
  long long integer_or(std::string_view key, long long fallback) const;
  /// A string or nothing when absent; InputError if not a string.
  std::optional<std::string> string(std::string_view key) const;
  /// A required string.
  std::string required_string(std::string_view key) const;
  /// One of the names of an enum (its EnumNames table), `fallback` when absent; InputError
  /// "expected <the names>, got ..." otherwise.
  template <typename Enum, std::size_t N>
  Enum choice_or(std::string_view key, const EnumNames<Enum, N>& names, Enum fallback) const {
    const std::optional<std::string> text = string(key);
    if (!text) return fallback;
    if (const std::optional<Enum> value = names.find(*text)) return *value;
    fail(key, "expected " + names.choices() + ", got \"" + *text + "\"");
  }
  /// A boolean, `fallback` when absent.
  bool boolean_or(std::string_view key, bool fallback) const;
  /// A list of [x, y] pairs of finite numbers (e.g. a B-H table), empty when absent.
  std::vector<std::pair<double, double>> pairs(std::string_view key) const;
  /// A sub-table or nothing when absent; InputError if the key is not a table.
  std::optional<TomlSection> table(std::string_view key) const;
  /// An array of tables (TOML [[key]]), empty when absent.
  std::vector<TomlSection> table_array(std::string_view key) const;
  /// The raw node of a key (nullptr when absent).
  const toml::node* node(std::string_view key) const;

  /// "file:line: path.key" for a key of this table (the table's line when the key is absent).
  std::string where(std::string_view key) const;
  /// "file:line: path" for the table itself.
  std::string where() const;
  /// Throws InputError "<where(key)>: <message>".
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;

  const toml::table& raw() const { return *table_; }
  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }

 private:
  std::string key_path(std::string_view key) const;
  const toml::table* table_;
  std::string path_;
  std::string file_;
};

/// Parses TOML text; a syntax error becomes an InputError "file:line:col: message".
toml::table parse_toml(std::string_view text, const std::string& file);

/// Reads and parses a TOML file; InputError if it cannot be read or parsed.
toml::table parse_toml_file(const std::string& path);

/// The whole content of an input file (core/input_file.hpp: regular files only, bounded size).
using ::rheomag::read_input_file;

/// `text` without a leading UTF-8 byte-order mark (what many Windows tools write first).
std::string_view without_byte_order_mark(std::string_view text);

/// Finite-number formatting for messages (shortest round-trip form).
std::string format_number(double value);

}  // namespace rheomag::cases
