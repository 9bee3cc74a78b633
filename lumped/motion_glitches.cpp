#include "lumped/motion_glitches.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "lumped/recording_io.hpp"

namespace rheomag::lumped {

namespace {

/// The `q`-quantile of `x` (nearest rank; `x` is copied).
double quantile(std::vector<double> x, double q) {
  const auto k = static_cast<std::size_t>(q * static_cast<double>(x.size() - 1));
  std::nth_element(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(k), x.end());
  return x[k];
}

/// Departure of sample k from its neighbours' path: the mean of both inside, the straight line
/// through the next two at an end.
double departure(const std::vector<double>& u, std::size_t k) {
  const std::size_t n = u.size();
  if (k == 0) return u[0] - (2.0 * u[1] - u[2]);
  if (k == n - 1) return u[n - 1] - (2.0 * u[n - 2] - u[n - 3]);
  return u[k] - 0.5 * (u[k - 1] + u[k + 1]);
}

/// How far the neighbours the departure is measured against differ from each other.
double neighbour_gap(const std::vector<double>& u, std::size_t k) {
  const std::size_t n = u.size();
  if (k == 0) return std::abs(u[2] - u[1]);
  if (k == n - 1) return std::abs(u[n - 2] - u[n - 3]);
  return std::abs(u[k + 1] - u[k - 1]);
}

/// True where the displacement `x` moved as the velocity sample v[k] says (one of its backward,
/// forward or central differences within `tolerance` of it).
bool displacement_follows(const std::vector<double>& v, const std::vector<double>& x,
                          const std::vector<double>& t, std::size_t k, double tolerance) {
  const std::size_t n = v.size();
  const auto near = [&](std::size_t a, std::size_t b) {
    return std::abs(v[k] - (x[b] - x[a]) / (t[b] - t[a])) < tolerance;
  };
  return (k > 0 && near(k - 1, k)) || (k + 1 < n && near(k, k + 1)) ||
         (k > 0 && k + 1 < n && near(k - 1, k + 1));
}

}  // namespace

bool is_motion_column(const std::string& column) {
  return column == "displacement" || column == "velocity" || column == "flow";
}

MotionGlitches find_motion_glitches(const std::vector<double>& u, const std::vector<double>& t,
                                    const std::vector<double>* displacement) {
  MotionGlitches found;
  const std::size_t n = u.size();
  if (n < 8 || t.size() != n || (displacement && displacement->size() != n)) return found;
  std::vector<double> d(n);
  for (std::size_t k = 0; k < n; ++k) d[k] = departure(u, k);
  // Robust scale of the departure (white noise of std s gives sqrt(1.5) s; a smooth signal ~0).
  std::vector<double> abs_d(d.size());
  std::transform(d.begin(), d.end(), abs_d.begin(), [](double x) { return std::abs(x); });
  const double scale = 1.4826 * quantile(abs_d, 0.5);
  const double spread = quantile(u, 0.99) - quantile(u, 0.01);
  if (!(spread > 0.0)) return found;
  const double bar = std::max(kGlitchDeviations * scale, kGlitchSpreadFraction * spread);
  for (std::size_t k = 0; k < n; ++k)
    if (std::abs(d[k]) > bar && neighbour_gap(u, k) < 0.5 * std::abs(d[k]) &&
        !(displacement && displacement_follows(u, *displacement, t, k, 0.5 * std::abs(d[k])))) {
      found.samples.push_back(k);
      found.largest = std::max(found.largest, std::abs(d[k]));
    }
  if (static_cast<double>(found.samples.size()) > kGlitchMaxFraction * static_cast<double>(n))
    return {};
  return found;
}

MotionGlitches find_motion_glitches(const Recording& rec, const std::string& column) {
  if (!is_motion_column(column)) return {};
  const auto x = rec.columns.find("displacement");
  const bool velocity = column == "velocity" && x != rec.columns.end();
  return find_motion_glitches(rec.column(column), rec.t, velocity ? &x->second : nullptr);
}

std::vector<double> column_without_glitches(const Recording& rec, const std::string& column) {
  const MotionGlitches glitches = find_motion_glitches(rec, column);
  if (glitches.samples.empty()) return rec.column(column);
  return without_glitches(rec.column(column), glitches);
}

std::vector<double> without_glitches(std::vector<double> u, const MotionGlitches& glitches) {
  const std::size_t n = u.size();
  for (std::size_t k : glitches.samples) {
    if (k == 0)
      u[0] = 2.0 * u[1] - u[2];
    else if (k == n - 1)
      u[n - 1] = 2.0 * u[n - 2] - u[n - 3];
    else
      u[k] = 0.5 * (u[k - 1] + u[k + 1]);
  }
  return u;
}

std::string describe_glitches(const std::string& column, const MotionGlitches& glitches,
                              const std::vector<double>& t) {
  std::ostringstream o;
  const std::size_t first = glitches.samples.front();
  o << std::setprecision(3) << "column '" << column << "': " << glitches.samples.size()
    << (glitches.samples.size() == 1 ? " single sample" : " single samples")
    << " off the path of both neighbours, back on it at the next (first at t = " << t[first]
    << " s, sample " << first << "; the largest by " << glitches.largest << " "
    << column_si_unit(column)
    << "): " << (glitches.samples.size() == 1 ? "an acquisition glitch" : "acquisition glitches")
    << ", not motion";
  return o.str();
}

}  // namespace rheomag::lumped
