// Sums over mid-line field samples (see field_samples.hpp).

#include "fluid/field_samples.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace rheomag::fluid {

void check_field_samples(const GapFieldSamples& field, double start, double end, const char* what) {
  const auto& x = field.position;
  if (x.size() != field.b.size())
    throw InputError(std::string(what) + ": " + std::to_string(x.size()) + " positions but " +
                     std::to_string(field.b.size()) + " flux densities");
  if (x.size() < 2) throw InputError(std::string(what) + ": needs at least 2 field samples");
  const double slack = 1e-9 * (end - start);
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(field.b[i]))
      throw InputError(std::string(what) + ": field sample " + std::to_string(i) +
                       " is not finite");
    if (x[i] < start - slack || x[i] > end + slack)
      throw InputError(std::string(what) + ": field sample " + std::to_string(i) +
                       " lies outside the gap");
    if (i > 0 && !(x[i] > x[i - 1]))
      throw InputError(std::string(what) + ": field sample positions must increase strictly");
  }
}

double integrate_samples(const std::vector<double>& x, const std::vector<double>& f, double start,
                         double end) {
  double sum = f.front() * (x.front() - start) + f.back() * (end - x.back());
  for (std::size_t i = 1; i < x.size(); ++i) sum += 0.5 * (f[i] + f[i - 1]) * (x[i] - x[i - 1]);
  return sum;
}

double interpolate_samples(const std::vector<double>& x, const std::vector<double>& f, double at) {
  if (at <= x.front()) return f.front();
  if (at >= x.back()) return f.back();
  std::size_t i = 1;
  while (x[i] < at) ++i;
  const double w = (at - x[i - 1]) / (x[i] - x[i - 1]);
  return f[i - 1] + w * (f[i] - f[i - 1]);
}

std::vector<double> sample_magnitudes(const std::vector<double>& b) {
  std::vector<double> out(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) out[i] = std::abs(b[i]);
  return out;
}

}  // namespace rheomag::fluid
