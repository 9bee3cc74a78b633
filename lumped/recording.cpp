// Recording: column access with an error naming the file.

#include "lumped/recording.hpp"

#include <algorithm>
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
  if (std::any_of(first, last, [&](double v) { return v != *first; })) return;
  std::ostringstream message;
  message.precision(12);
  message << csv_path << ": column '" << name << "' is constant (" << *first << ") on samples "
          << begin << ":" << end << "; there is nothing to identify";
  throw InputError(message.str());
}

}  // namespace rheomag::lumped
