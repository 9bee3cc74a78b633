#pragma once
// Unit conversion of a plotted series (m -> mm, T -> mT, s -> ms).

#include <vector>

namespace rheomag::figures {

/// `values` times `factor`.
inline std::vector<double> scaled(const std::vector<double>& values, double factor) {
  std::vector<double> out;
  out.reserve(values.size());
  for (double v : values) out.push_back(factor * v);
  return out;
}

}  // namespace rheomag::figures
