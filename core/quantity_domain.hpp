#pragma once
// The declared domain of a physical quantity read from an input (positive, non-negative,
// an integer count, an interval): one check and one wording for every reader.

#include <limits>
#include <string>
#include <string_view>

namespace rheomag {

/// The values a quantity read from input may take: a finite number in an interval whose ends
/// are open or closed, optionally integers only, with the unit named in messages.
struct Domain {
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool lower_open = false;  ///< lower bound excluded
  bool upper_open = false;  ///< upper bound excluded
  bool integer = false;     ///< whole numbers only
  std::string_view unit;    ///< e.g. "m^2"; empty for pure numbers

  /// Any finite number.
  static constexpr Domain finite(std::string_view unit = {}) {
    Domain d;
    d.unit = unit;
    return d;
  }
  /// A finite number > 0.
  static constexpr Domain positive(std::string_view unit = {}) { return finite(unit).above(0.0); }
  /// A finite number >= 0.
  static constexpr Domain non_negative(std::string_view unit = {}) {
    Domain d = finite(unit);
    d.lower = 0.0;
    return d;
  }
  /// A whole number >= 1 (turns, counts).
  static constexpr Domain count() {
    Domain d;
    d.lower = 1.0;
    return d.whole();
  }
  /// A finite number in [lower, upper].
  static constexpr Domain between(double lower, double upper, std::string_view unit = {}) {
    Domain d = finite(unit);
    d.lower = lower;
    d.upper = upper;
    return d;
  }
  /// The same domain, whole numbers only.
  constexpr Domain whole() const {
    Domain d = *this;
    d.integer = true;
    return d;
  }
  /// The same domain with the lower end excluded.
  constexpr Domain above(double bound) const {
    Domain d = *this;
    d.lower = bound;
    d.lower_open = true;
    return d;
  }

  /// True if `value` is finite and in the domain.
  bool contains(double value) const;
  /// "a positive number (m^2)", "a whole number >= 1", "a number in (1, 100]".
  std::string describe() const;
  /// "" if `value` is in the domain, else "expected <describe()>, got <value>".
  std::string violation(double value) const;
};

}  // namespace rheomag
