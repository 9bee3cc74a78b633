#include "lumped/recording_excerpt.hpp"

#include <string>
#include <vector>

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

std::size_t thinning_factor(std::size_t samples, std::size_t max_samples) {
  if (max_samples == 0 || samples <= max_samples) return 1;
  return (samples + max_samples - 1) / max_samples;
}

Recording every_nth_sample(const Recording& rec, std::size_t factor) {
  if (factor <= 1) return rec;
  Recording thin;
  thin.meta = rec.meta;
  thin.csv_path = rec.csv_path;
  const std::size_t kept = (rec.t.size() + factor - 1) / factor;
  const auto pick = [&](const std::vector<double>& values) {
    std::vector<double> out;
    out.reserve(kept);
    for (std::size_t i = 0; i < values.size(); i += factor) out.push_back(values[i]);
    return out;
  };
  thin.t = pick(rec.t);
  for (const auto& [name, values] : rec.columns) thin.columns[name] = pick(values);
  return thin;
}

SampleRange thinned_range(SampleRange range, std::size_t factor) {
  if (factor <= 1) return range;
  return {(range.begin + factor - 1) / factor, (range.end + factor - 1) / factor};
}

std::string thinning_note(std::size_t samples, std::size_t factor) {
  const std::size_t tens = factor % 100, units = factor % 10;
  const char* suffix = (tens >= 11 && tens <= 13) ? "th"
                       : units == 1               ? "st"
                       : units == 2               ? "nd"
                       : units == 3               ? "rd"
                                                  : "th";
  return "every " + std::to_string(factor) + suffix + " of its " + std::to_string(samples) +
         " samples, as rheomag fits and diagnoses at most " + std::to_string(kMaxFitSamples) +
         " (for the full rate, give a shorter part of the recording)";
}

}  // namespace rheomag::lumped
