// The guard of every output against non-finite numbers (see finite_output.hpp).

#include "core/finite_output.hpp"

#include <cctype>
#include <cmath>

namespace rheomag {

namespace {

bool word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

/// True if `text` at `at` starts with `word`, ignoring case.
bool starts_with_nocase(std::string_view text, std::size_t at, std::string_view word) {
  if (text.size() - at < word.size()) return false;
  for (std::size_t k = 0; k < word.size(); ++k)
    if (std::tolower(static_cast<unsigned char>(text[at + k])) != word[k]) return false;
  return true;
}

/// Length of a non-finite spelling at `at` ("nan", "inf", "infinity"), or 0.
std::size_t non_finite_length(std::string_view text, std::size_t at) {
  for (std::string_view word : {"infinity", "inf", "nan"})
    if (starts_with_nocase(text, at, word) &&
        (at + word.size() == text.size() || !word_char(text[at + word.size()])))
      return word.size();
  return 0;
}

/// The first non-finite number under `j`, as a key path; empty if none.
std::optional<std::string> non_finite_path(const nlohmann::json& j, const std::string& path) {
  if (j.is_number_float()) {
    if (std::isfinite(j.get<double>())) return std::nullopt;
    return path.empty() ? std::string("(the document itself)") : path;
  }
  if (j.is_object()) {
    for (const auto& [key, value] : j.items())
      if (auto p = non_finite_path(value, path.empty() ? key : path + "." + key)) return p;
  } else if (j.is_array()) {
    for (std::size_t k = 0; k < j.size(); ++k)
      if (auto p = non_finite_path(j[k], path + "[" + std::to_string(k) + "]")) return p;
  }
  return std::nullopt;
}

}  // namespace

std::optional<NonFiniteToken> find_non_finite_token(std::string_view text) {
  std::size_t line = 1, line_start = 0;
  for (std::size_t at = 0; at < text.size(); ++at) {
    if (text[at] == '\n') {
      ++line;
      line_start = at + 1;
      continue;
    }
    if (at > 0 && word_char(text[at - 1])) continue;
    const std::size_t length = non_finite_length(text, at);
    if (length == 0) continue;
    std::size_t begin = at;
    if (begin > line_start && (text[begin - 1] == '-' || text[begin - 1] == '+')) --begin;
    const std::size_t end = text.find('\n', at);
    return NonFiniteToken{
        line, std::string(text.substr(begin, at + length - begin)),
        std::string(text.substr(line_start,
                                (end == std::string_view::npos ? text.size() : end) - line_start))};
  }
  return std::nullopt;
}

void require_finite_text(std::string_view text, std::string_view output) {
  const auto bad = find_non_finite_token(text);
  if (!bad) return;
  throw NonFiniteOutputError(std::string(output) + ":" + std::to_string(bad->line) +
                             ": the result holds a non-finite number ('" + bad->token + "' in \"" +
                             bad->line_text + "\"); it was not written");
}

void require_finite_json(const nlohmann::json& j, std::string_view output) {
  const auto path = non_finite_path(j, "");
  if (!path) return;
  throw NonFiniteOutputError(std::string(output) + ": key '" + *path +
                             "' is not a finite number; the result was not written");
}

void require_finite_values(std::span<const double> values, std::string_view output,
                           std::string_view what) {
  for (std::size_t k = 0; k < values.size(); ++k)
    if (!std::isfinite(values[k]))
      throw NonFiniteOutputError(std::string(output) + ": " + std::string(what) + " value " +
                                 std::to_string(k) + " is not a finite number (" +
                                 std::to_string(values[k]) + "); the result was not written");
}

std::string finite_json_text(const nlohmann::json& j, std::string_view output, int indent) {
  require_finite_json(j, output);
  return j.dump(indent);
}

}  // namespace rheomag
