#include "magnetostatics3d/revolve.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace rheomag::magnetostatics3d {
namespace {

bool contains_angle(const std::vector<double>& list, double phi) {
  return std::any_of(list.begin(), list.end(),
                     [phi](double a) { return std::abs(a - phi) < 1e-9; });
}

}  // namespace

Revolution make_revolution(double span, double max_step, std::vector<double> breaks) {
  Revolution rev;
  rev.full = std::abs(span - kTwoPi) < 1e-9;
  breaks.push_back(0.0);
  breaks.push_back(span);
  std::sort(breaks.begin(), breaks.end());
  rev.angles.push_back(breaks.front());
  for (std::size_t i = 1; i < breaks.size(); ++i) {
    const double gap = breaks[i] - breaks[i - 1];
    if (gap < 1e-9) continue;
    const int n = std::max(1, static_cast<int>(std::ceil(gap / max_step - 1e-9)));
    for (int k = 1; k <= n; ++k) rev.angles.push_back(breaks[i - 1] + gap * k / n);
  }
  return rev;
}

int interval_of(const Revolution& rev, double phi) {
  const int n = static_cast<int>(rev.angles.size()) - 1;
  if (rev.full) phi = std::fmod(std::fmod(phi, kTwoPi) + kTwoPi, kTwoPi);
  const auto it = std::upper_bound(rev.angles.begin(), rev.angles.end(), phi);
  return std::clamp(static_cast<int>(it - rev.angles.begin()) - 1, 0, n - 1);
}

Plc revolve(const cases::Problem& closed, const Revolution& rev,
            const std::vector<double>& max_volume, const std::vector<double>& walls) {
  const mesh::Pslg& g = closed.geometry;
  Plc plc;
  plc.source = g.source;
  plc.default_region = g.default_region;
  const int intervals = static_cast<int>(rev.angles.size()) - 1;
  const int columns = rev.full ? intervals : intervals + 1;  // distinct angles
  double scale = 0.0;
  for (const mesh::Point& p : g.points) scale = std::max(scale, std::hypot(p.r, p.z));
  const double axis_tol = 1e-12 * scale;

  // Point (i, k): PSLG point i at angle column k; points on the axis are one 3D point.
  std::vector<int> first(g.points.size());
  std::vector<bool> on_axis(g.points.size());
  for (std::size_t i = 0; i < g.points.size(); ++i) {
    const mesh::Point& p = g.points[i];
    if (p.r < -axis_tol) throw InputError(g.source + ": a point has r < 0 (revolving about z)");
    on_axis[i] = p.r <= axis_tol;
    first[i] = static_cast<int>(plc.points.size());
    for (int k = 0; k < (on_axis[i] ? 1 : columns); ++k) {
      const double phi = rev.angles[k];
      plc.points.emplace_back(p.r * std::cos(phi), p.r * std::sin(phi), p.z);
    }
  }
  auto point = [&](int i, int k) {
    if (on_axis[i]) return first[i];
    return first[i] + (k == intervals && rev.full ? 0 : k);
  };

  for (const mesh::Segment& s : g.segments) {
    if (on_axis[s.a] && on_axis[s.b]) continue;  // the axis: an edge of the end planes only
    const FaceKind kind = s.boundary >= 0 ? FaceKind::outer : FaceKind::interior;
    for (int k = 0; k < intervals; ++k) {
      std::vector<int> poly{point(s.a, k), point(s.b, k), point(s.b, k + 1), point(s.a, k + 1)};
      poly.erase(std::unique(poly.begin(), poly.end()), poly.end());
      if (poly.front() == poly.back()) poly.pop_back();
      plc.facets.push_back({{poly}, kind});
    }
  }
  // Meridian facets: the wedge's end planes and the feature walls.
  auto meridian = [&](int k, FaceKind kind) {
    PlcFacet f;
    f.kind = kind;
    for (const mesh::Segment& s : g.segments) f.polygons.push_back({point(s.a, k), point(s.b, k)});
    plc.facets.push_back(std::move(f));
  };
  if (!rev.full) {
    meridian(0, FaceKind::symmetry);
    meridian(intervals, FaceKind::symmetry);
  }
  for (int k = 0; k < columns; ++k) {
    if ((rev.full || (k > 0 && k < intervals)) && contains_angle(walls, rev.angles[k]))
      meridian(k, FaceKind::interior);
  }

  // Seeds: the mid-angle section of an interval is the PSLG scaled radially by cos(half step).
  for (int k = 0; k < intervals; ++k) {
    const double half = 0.5 * (rev.angles[k + 1] - rev.angles[k]);
    const double phi = rev.angles[k] + half;
    for (std::size_t r = 0; r < g.regions.size(); ++r) {
      const mesh::Point& s = g.regions[r].seed;
      const Eigen::Vector3d x(s.r * std::cos(half) * std::cos(phi),
                              s.r * std::cos(half) * std::sin(phi), s.z);
      if (g.regions[r].hole) {
        plc.holes.push_back(x);
      } else {
        plc.regions.push_back({x, static_cast<int>(r), max_volume[r]});
      }
    }
  }
  return plc;
}

}  // namespace rheomag::magnetostatics3d
