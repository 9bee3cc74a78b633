// Recording: column access with an error naming the file.

#include "lumped/recording.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/error.hpp"

namespace rheomag::lumped {

const std::vector<double>& Recording::column(const std::string& name) const {
  auto it = columns.find(name);
  if (it == columns.end())
    throw InputError(csv_path + ": no column '" + name + "' (the model needs it)");
  return it->second;
}

void Recording::require_varying(const std::string& name, std::size_t begin, std::size_t end) const {
  const std::vector<double>& values = column(name);
  end = std::min(end, values.size());
  if (begin >= end) return;
  const auto first = values.begin() + static_cast<std::ptrdiff_t>(begin);
  const auto last = values.begin() + static_cast<std::ptrdiff_t>(end);
  // A spread below 1e-9 of the values' size (as diagnose's flatness test) is rounding around a
  // constant, not a signal: 5 +- 1e-13 gave FIT -103 % with exit 0.
  const auto [lo, hi] = std::minmax_element(first, last);
  if (*hi - *lo > 1e-9 * std::max(std::abs(*lo), std::abs(*hi))) return;
  std::ostringstream message;
  message.precision(12);
  message << csv_path << ": column '" << name << "' is constant (";
  if (*hi == *lo)
    message << *lo;
  else
    message << "to 9 significant digits: " << *lo << ", spread " << std::setprecision(3)
            << *hi - *lo;
  message << ") on samples " << begin << ":" << end << "; there is nothing to identify";
  throw InputError(message.str());
}

}  // namespace rheomag::lumped
