// Declared domains of input quantities and their one wording.

#include "core/quantity_domain.hpp"

#include <cmath>
#include <sstream>

namespace rheomag {

namespace {

std::string number_text(double value) {
  std::ostringstream out;
  out.precision(12);
  out << value;
  return out.str();
}

}  // namespace

bool Domain::contains(double value) const {
  if (!std::isfinite(value)) return false;
  if (lower_open ? !(value > lower) : !(value >= lower)) return false;
  if (upper_open ? !(value < upper) : !(value <= upper)) return false;
  return !integer || std::floor(value) == value;
}

std::string Domain::describe() const {
  std::string text = integer ? "a whole number" : "a number";
  const bool has_lower = std::isfinite(lower), has_upper = std::isfinite(upper);
  if (!integer && !has_upper && lower == 0.0 && lower_open)
    text = "a positive number";
  else if (has_lower && has_upper)
    text += std::string(" in ") + (lower_open ? "(" : "[") + number_text(lower) + ", " +
            number_text(upper) + (upper_open ? ")" : "]");
  else if (has_lower)
    text += std::string(lower_open ? " > " : " >= ") + number_text(lower);
  else if (has_upper)
    text += std::string(upper_open ? " < " : " <= ") + number_text(upper);
  else if (!integer)
    text = "a finite number";
  if (!unit.empty()) text += " (" + std::string(unit) + ")";
  return text;
}

std::string Domain::violation(double value) const {
  if (contains(value)) return {};
  return "expected " + describe() + ", got " + number_text(value);
}

}  // namespace rheomag
