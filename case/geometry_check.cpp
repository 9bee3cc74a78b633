// Polygon checks: simplicity, disjoint interiors, interior points.

#include "case/geometry_check.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "case/toml_section.hpp"
#include "core/error.hpp"

namespace rheomag::cases {
namespace {

using mesh::Point;

std::string text(const Point& p) {
  std::ostringstream out;
  out.precision(6);
  out << "(" << p.r * 1e3 << ", " << p.z * 1e3 << ") mm";
  return out.str();
}

double cross(const Point& a, const Point& b, const Point& c) {
  return (b.r - a.r) * (c.z - a.z) - (b.z - a.z) * (c.r - a.r);
}

double distance(const Point& a, const Point& b) {
  return std::hypot(a.r - b.r, a.z - b.z);
}

/// Side of c relative to the line a-b: -1, 0 (within tolerance) or +1.
int side(const Point& a, const Point& b, const Point& c, double tolerance) {
  const double length = distance(a, b);
  if (length == 0.0) return 0;
  const double d = cross(a, b, c) / length;
  return d > tolerance ? 1 : (d < -tolerance ? -1 : 0);
}

/// Distance from p to segment a-b.
double segment_distance(const Point& p, const Point& a, const Point& b) {
  const double dr = b.r - a.r, dz = b.z - a.z;
  const double length2 = dr * dr + dz * dz;
  double t = length2 > 0.0 ? ((p.r - a.r) * dr + (p.z - a.z) * dz) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.r - (a.r + t * dr), p.z - (a.z + t * dz));
}

/// True if the closed segments a-b and c-d share any point (within tolerance).
bool segments_touch(const Point& a, const Point& b, const Point& c, const Point& d,
                    double tolerance) {
  const int s1 = side(a, b, c, tolerance), s2 = side(a, b, d, tolerance);
  const int s3 = side(c, d, a, tolerance), s4 = side(c, d, b, tolerance);
  if (s1 * s2 < 0 && s3 * s4 < 0) return true;
  return segment_distance(c, a, b) <= tolerance || segment_distance(d, a, b) <= tolerance ||
         segment_distance(a, c, d) <= tolerance || segment_distance(b, c, d) <= tolerance;
}

/// True if the open segments a-b and c-d cross at a single interior point of both.
bool segments_cross(const Point& a, const Point& b, const Point& c, const Point& d,
                    double tolerance) {
  return side(a, b, c, tolerance) * side(a, b, d, tolerance) < 0 &&
         side(c, d, a, tolerance) * side(c, d, b, tolerance) < 0;
}

struct Box {
  double r0, r1, z0, z1;
};

Box bounding_box(const std::vector<Point>& polygon) {
  Box box{polygon[0].r, polygon[0].r, polygon[0].z, polygon[0].z};
  for (const Point& p : polygon) {
    box.r0 = std::min(box.r0, p.r);
    box.r1 = std::max(box.r1, p.r);
    box.z0 = std::min(box.z0, p.z);
    box.z1 = std::max(box.z1, p.z);
  }
  return box;
}

/// Edge midpoints of `polygon` after splitting its edges at the vertices of `other` on them.
std::vector<Point> split_midpoints(const std::vector<Point>& polygon,
                                   const std::vector<Point>& other, double tolerance) {
  std::vector<Point> result;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = polygon[i];
    const Point& b = polygon[(i + 1) % n];
    std::vector<double> cuts{0.0, 1.0};
    const double dr = b.r - a.r, dz = b.z - a.z;
    const double length2 = dr * dr + dz * dz;
    for (const Point& p : other) {
      if (segment_distance(p, a, b) > tolerance) continue;
      cuts.push_back(((p.r - a.r) * dr + (p.z - a.z) * dz) / length2);
    }
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double t = 0.5 * (cuts[k] + cuts[k + 1]);
      if (cuts[k + 1] - cuts[k] > 1e-12) result.push_back({a.r + t * dr, a.z + t * dz});
    }
  }
  return result;
}

}  // namespace

double signed_area(const std::vector<Point>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point& a = polygon[i];
    const Point& b = polygon[(i + 1) % polygon.size()];
    twice += a.r * b.z - b.r * a.z;
  }
  return 0.5 * twice;
}

Location locate(const Point& p, const std::vector<Point>& polygon, double tolerance) {
  bool inside = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point& a = polygon[i];
    const Point& b = polygon[j];
    if (segment_distance(p, a, b) <= tolerance) return Location::boundary;
    if ((a.z > p.z) != (b.z > p.z)) {
      const double r_cross = a.r + (p.z - a.z) * (b.r - a.r) / (b.z - a.z);
      if (p.r < r_cross) inside = !inside;
    }
  }
  return inside ? Location::inside : Location::outside;
}

void check_simple_polygon(const RegionOutline& region, double tolerance) {
  const std::vector<Point>& poly = region.outline;
  const std::size_t n = poly.size();
  if (n < 3)
    throw InputError(region.where + ": region '" + region.name +
                     "': outline needs at least 3 distinct points, got " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i) {
    if (distance(poly[i], poly[(i + 1) % n]) <= tolerance)
      throw InputError(region.where + ": region '" + region.name + "': repeated point " +
                       text(poly[i]) + " (point " + std::to_string(i + 1) +
                       "): the next point lies within " + format_number(tolerance) +
                       " m, the merge tolerance (1e-9 of the largest coordinate of the case; a "
                       "coordinate far from the rest makes it large)");
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = poly[i];
    const Point& b = poly[(i + 1) % n];
    // The neighbour edge (b, c) must not fold back onto (a, b).
    const Point& c = poly[(i + 2) % n];
    if (side(a, b, c, tolerance) == 0 &&
        (c.r - b.r) * (b.r - a.r) + (c.z - b.z) * (b.z - a.z) < 0.0)
      throw InputError(region.where + ": region '" + region.name +
                       "': outline folds back on itself at " + text(b));
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
      const Point& d = poly[j];
      const Point& e = poly[(j + 1) % n];
      if (segments_touch(a, b, d, e, tolerance))
        throw InputError(region.where + ": region '" + region.name +
                         "': outline intersects itself: edge " + text(a) + "-" + text(b) +
                         " meets edge " + text(d) + "-" + text(e));
    }
  }
  const Box box = bounding_box(poly);
  const double extent = std::max(box.r1 - box.r0, box.z1 - box.z0);
  if (std::abs(signed_area(poly)) <= tolerance * extent)
    throw InputError(region.where + ": region '" + region.name +
                     "': outline encloses no area (all points on one line)");
}

void check_disjoint(const RegionOutline& a, const RegionOutline& b, double tolerance) {
  const Box ba = bounding_box(a.outline), bb = bounding_box(b.outline);
  if (ba.r1 < bb.r0 - tolerance || bb.r1 < ba.r0 - tolerance || ba.z1 < bb.z0 - tolerance ||
      bb.z1 < ba.z0 - tolerance)
    return;
  auto overlap = [&](const std::string& detail) {
    throw InputError(b.where + ": region '" + b.name + "' overlaps region '" + a.name + "' (" +
                     a.where + "): " + detail);
  };
  const std::size_t na = a.outline.size(), nb = b.outline.size();
  for (std::size_t i = 0; i < na; ++i)
    for (std::size_t j = 0; j < nb; ++j)
      if (segments_cross(a.outline[i], a.outline[(i + 1) % na], b.outline[j],
                         b.outline[(j + 1) % nb], tolerance))
        overlap("their edges cross near " + text(a.outline[i]));
  auto inside_test = [&](const std::vector<Point>& points, const RegionOutline& other) {
    for (const Point& p : points)
      if (locate(p, other.outline, tolerance) == Location::inside)
        overlap("point " + text(p) + " lies inside '" + other.name + "'");
  };
  inside_test(b.outline, a);
  inside_test(a.outline, b);
  inside_test(split_midpoints(b.outline, a.outline, tolerance), a);
  inside_test(split_midpoints(a.outline, b.outline, tolerance), b);
  inside_test({interior_point(b.outline)}, a);
  inside_test({interior_point(a.outline)}, b);
}

Point interior_point(const std::vector<Point>& polygon) {
  std::vector<double> levels;
  for (const Point& p : polygon) levels.push_back(p.z);
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  Point best = polygon[0];
  double best_clearance = -1.0;
  const std::size_t n = polygon.size();
  for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
    const double z = 0.5 * (levels[k] + levels[k + 1]);
    const double half_height = 0.5 * (levels[k + 1] - levels[k]);
    std::vector<double> crossings;
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
      const Point& a = polygon[i];
      const Point& b = polygon[j];
      if ((a.z > z) != (b.z > z)) crossings.push_back(a.r + (z - a.z) * (b.r - a.r) / (b.z - a.z));
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t c = 0; c + 1 < crossings.size(); c += 2) {
      const double clearance = std::min(0.5 * (crossings[c + 1] - crossings[c]), half_height);
      if (clearance > best_clearance) {
        best_clearance = clearance;
        best = {0.5 * (crossings[c] + crossings[c + 1]), z};
      }
    }
  }
  return best;
}

}  // namespace rheomag::cases
