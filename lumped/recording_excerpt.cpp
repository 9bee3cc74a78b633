#include "lumped/recording_excerpt.hpp"

#include <string>

#include "core/error.hpp"

namespace rheomag::lumped {

Recording excerpt(const Recording& rec, SampleRange range) {
  if (range.begin >= range.end || range.end > rec.t.size())
    throw InputError(rec.csv_path + ": samples " + std::to_string(range.begin) + ":" +
                     std::to_string(range.end) + " are not inside its " +
                     std::to_string(rec.t.size()) + " samples");
  Recording part;
  part.meta = rec.meta;
  part.csv_path = rec.csv_path;
  const auto b = rec.t.begin() + static_cast<std::ptrdiff_t>(range.begin);
  const auto e = rec.t.begin() + static_cast<std::ptrdiff_t>(range.end);
  part.t.assign(b, e);
  for (const auto& [name, values] : rec.columns)
    part.columns[name].assign(values.begin() + static_cast<std::ptrdiff_t>(range.begin),
                              values.begin() + static_cast<std::ptrdiff_t>(range.end));
  return part;
}

}  // namespace rheomag::lumped
