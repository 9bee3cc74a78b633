#pragma once
// The one guard between rheomag's numbers and its outputs: a non-finite value (NaN, inf) never
// reaches stdout, a JSON document or an output file; it ends the command with exit 3 instead.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "core/error.hpp"

namespace rheomag {

/// A non-finite number on its way to an output (a ConvergenceError: the CLI exits with 3). The
/// message names the output and the key or line holding it; the CLI adds the command line that
/// produced it.
class NonFiniteOutputError : public ConvergenceError {
 public:
  using ConvergenceError::ConvergenceError;
};

/// A token spelling a non-finite number in text output.
struct NonFiniteToken {
  std::size_t line = 0;   ///< 1-based line number
  std::string token;      ///< as written ("-nan", "inf", "Infinity")
  std::string line_text;  ///< the whole line (without its newline)
};

/// The first token of `text` that spells a non-finite number: "nan" or "inf"/"infinity" with an
/// optional sign, in any case, not part of a longer word ("information", "isNaN" do not count).
std::optional<NonFiniteToken> find_non_finite_token(std::string_view text);

/// Throws NonFiniteOutputError naming `output`, the line and the token when `text` holds a
/// non-finite number.
void require_finite_text(std::string_view text, std::string_view output);

/// Throws NonFiniteOutputError naming `output` and the key path (e.g. "fits[2].fit_percent")
/// of the first non-finite number in `j` (nlohmann would print it as null).
void require_finite_json(const nlohmann::json& j, std::string_view output);

/// Throws NonFiniteOutputError naming `output`, `what` (e.g. "field 'B' per cell") and the
/// index of the first non-finite number in `values` (for binary outputs such as .vtu files).
void require_finite_values(std::span<const double> values, std::string_view output,
                           std::string_view what);

/// `j` as text (nlohmann's dump with `indent`; -1 is one line) once require_finite_json passed.
std::string finite_json_text(const nlohmann::json& j, std::string_view output, int indent = -1);

}  // namespace rheomag
