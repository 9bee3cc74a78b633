// Validation and clean-up of a PSLG before triangulation (see pslg_check.hpp).

#include "mesh/pslg_check.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>
#include <utility>

#include "core/error.hpp"
#include "mesh/box_grid.hpp"

namespace rheomag::mesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

/// Relative distance (to the bounding box) below which two points are taken as one.
constexpr double kRelativeTolerance = 1e-9;

[[noreturn]] void fail(const Pslg& pslg, const std::string& what) {
  throw InputError(pslg_name(pslg) + ": " + what);
}

/// Refuses maximum lengths that cut the segments into more than kMaxSegmentPieces pieces.
void check_segment_pieces(const Pslg& pslg) {
  double total = 0.0;
  for (std::size_t k = 0; k < pslg.segments.size(); ++k) {
    const Segment& s = pslg.segments[k];
    if (!(s.max_length > 0.0) || s.a < 0 || s.b < 0 ||
        std::max(s.a, s.b) >= static_cast<int>(pslg.points.size()))
      continue;  // bad indices are reported by the checks that follow
    const Point& a = pslg.points[static_cast<std::size_t>(s.a)];
    const Point& b = pslg.points[static_cast<std::size_t>(s.b)];
    total += std::ceil(std::hypot(b.r - a.r, b.z - a.z) / s.max_length);
    if (!(total <= kMaxSegmentPieces))
      fail(pslg, "segment " + std::to_string(k) + " " + format_point(a) + "-" + format_point(b) +
                     " with a maximum element length of " + format_number(s.max_length) +
                     " m cuts the boundaries into more than " + format_number(kMaxSegmentPieces) +
                     " pieces; expected a larger maximum length (a unit mistake?)");
  }
}

Kernel::Point_2 to_cgal(const Point& p) {
  return {p.r, p.z};
}

/// Squared distance from p to the segment ab, and the parameter of the closest point on ab.
std::pair<double, double> distance_to_segment(const Point& p, const Point& a, const Point& b) {
  const double dr = b.r - a.r, dz = b.z - a.z;
  const double length_sq = dr * dr + dz * dz;
  double t = ((p.r - a.r) * dr + (p.z - a.z) * dz) / length_sq;
  t = std::clamp(t, 0.0, 1.0);
  const double er = a.r + t * dr - p.r, ez = a.z + t * dz - p.z;
  return {er * er + ez * ez, t};
}

void check_finite(const Pslg& pslg) {
  for (std::size_t i = 0; i < pslg.points.size(); ++i) {
    const Point& p = pslg.points[i];
    if (!std::isfinite(p.r) || !std::isfinite(p.z))
      fail(pslg, "point " + std::to_string(i) + " has a non-finite coordinate " + format_point(p) +
                     "; expected finite numbers in metres");
  }
  for (std::size_t i = 0; i < pslg.regions.size(); ++i) {
    const RegionSeed& s = pslg.regions[i];
    if (!std::isfinite(s.seed.r) || !std::isfinite(s.seed.z))
      fail(pslg, "region " + std::to_string(i) + " '" + s.name + "' has a non-finite seed point " +
                     format_point(s.seed));
    if (!std::isfinite(s.mesh_size) || s.mesh_size < 0.0)
      fail(pslg, "region " + std::to_string(i) + " '" + s.name + "' has mesh size " +
                     format_number(s.mesh_size) +
                     "; expected a finite length >= 0 (0 = automatic)");
  }
  for (std::size_t i = 0; i < pslg.segments.size(); ++i) {
    const Segment& s = pslg.segments[i];
    const int n = static_cast<int>(pslg.points.size());
    if (s.a < 0 || s.a >= n || s.b < 0 || s.b >= n)
      fail(pslg, "segment " + std::to_string(i) + " joins points " + std::to_string(s.a) + " and " +
                     std::to_string(s.b) + "; expected indices in [0, " + std::to_string(n) + ")");
    if (s.a == s.b)
      fail(pslg, "segment " + std::to_string(i) + " has zero length (both ends are point " +
                     std::to_string(s.a) + " " + format_point(pslg.points[s.a]) + ")");
    if (!std::isfinite(s.max_length) || s.max_length < 0.0)
      fail(pslg, "segment " + std::to_string(i) + " has maximum edge length " +
                     format_number(s.max_length) + "; expected a finite length >= 0");
  }
  if (pslg.default_region < -1 || pslg.default_region >= static_cast<int>(pslg.regions.size()))
    fail(pslg, "default region " + std::to_string(pslg.default_region) +
                   " does not exist; expected -1 or an index in [0, " +
                   std::to_string(pslg.regions.size()) + ")");
}

/// Indices of the points sorted by r (then z), for range queries along r.
std::vector<int> sorted_by_r(const std::vector<Point>& points) {
  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    return std::pair(points[i].r, points[i].z) < std::pair(points[j].r, points[j].z);
  });
  return order;
}

void check_distinct_points(const Pslg& pslg, const std::vector<int>& by_r, double tolerance) {
  const auto& pts = pslg.points;
  for (std::size_t k = 0; k < by_r.size(); ++k) {
    const Point& p = pts[by_r[k]];
    for (std::size_t m = k + 1; m < by_r.size() && pts[by_r[m]].r - p.r <= tolerance; ++m) {
      const Point& q = pts[by_r[m]];
      if (std::hypot(q.r - p.r, q.z - p.z) <= tolerance) {
        const int i = std::min(by_r[k], by_r[m]), j = std::max(by_r[k], by_r[m]);
        fail(pslg, "points " + std::to_string(i) + " and " + std::to_string(j) + " coincide at " +
                       format_point(pts[i]) + " (within " + format_number(tolerance) +
                       " m, the merge tolerance: 1e-9 of the geometry's extent; a coordinate far "
                       "from the rest makes it large); expected distinct points (merge them)");
      }
    }
  }
}

/// Input segments split at every input point lying on their interior.
std::vector<PreparedSegment> split_at_points(const Pslg& pslg, const std::vector<int>& by_r,
                                             double tolerance) {
  const auto& pts = pslg.points;
  std::vector<PreparedSegment> pieces;
  for (std::size_t s = 0; s < pslg.segments.size(); ++s) {
    const Segment& seg = pslg.segments[s];
    const Point& a = pts[seg.a];
    const Point& b = pts[seg.b];
    const double r_lo = std::min(a.r, b.r) - tolerance, r_hi = std::max(a.r, b.r) + tolerance;
    const double z_lo = std::min(a.z, b.z) - tolerance, z_hi = std::max(a.z, b.z) + tolerance;
    auto first = std::lower_bound(by_r.begin(), by_r.end(), r_lo,
                                  [&](int i, double r) { return pts[i].r < r; });
    std::vector<std::pair<double, int>> on_segment;  // (parameter along ab, point)
    for (auto it = first; it != by_r.end() && pts[*it].r <= r_hi; ++it) {
      const int i = *it;
      if (i == seg.a || i == seg.b || pts[i].z < z_lo || pts[i].z > z_hi) continue;
      auto [dist_sq, t] = distance_to_segment(pts[i], a, b);
      if (dist_sq <= tolerance * tolerance && t > 0.0 && t < 1.0) on_segment.emplace_back(t, i);
    }
    std::sort(on_segment.begin(), on_segment.end());
    int from = seg.a;
    on_segment.emplace_back(1.0, seg.b);
    for (const auto& [t, to] : on_segment) {
      pieces.push_back({from, to, seg.boundary, seg.max_length, static_cast<int>(s)});
      from = to;
    }
  }
  return pieces;
}

/// Keeps one copy of segments given more than once (same end points, either direction).
std::vector<PreparedSegment> merge_duplicates(const Pslg& pslg,
                                              const std::vector<PreparedSegment>& pieces) {
  std::map<std::pair<int, int>, std::size_t> index_of;
  std::vector<PreparedSegment> merged;
  for (const PreparedSegment& p : pieces) {
    const auto key = std::minmax(p.a, p.b);
    auto [it, inserted] = index_of.try_emplace(key, merged.size());
    if (inserted) {
      merged.push_back(p);
      continue;
    }
    PreparedSegment& kept = merged[it->second];
    if (kept.boundary >= 0 && p.boundary >= 0 && kept.boundary != p.boundary)
      fail(pslg, "segments " + std::to_string(kept.source_segment) + " and " +
                     std::to_string(p.source_segment) + " overlap between " +
                     format_point(pslg.points[p.a]) + " and " + format_point(pslg.points[p.b]) +
                     " but carry different boundary conditions (" + std::to_string(kept.boundary) +
                     " and " + std::to_string(p.boundary) + ")");
    kept.boundary = std::max(kept.boundary, p.boundary);
    if (p.max_length > 0.0)
      kept.max_length =
          kept.max_length > 0.0 ? std::min(kept.max_length, p.max_length) : p.max_length;
  }
  return merged;
}

/// Throws if two segments that share no end point intersect (exact predicates).
void check_no_crossings(const Pslg& pslg, const std::vector<PreparedSegment>& segments) {
  const auto& pts = pslg.points;
  auto r_min = [&](const PreparedSegment& s) { return std::min(pts[s.a].r, pts[s.b].r); };
  auto r_max = [&](const PreparedSegment& s) { return std::max(pts[s.a].r, pts[s.b].r); };
  std::vector<std::size_t> order(segments.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return std::pair(r_min(segments[i]), i) < std::pair(r_min(segments[j]), j);
  });
  for (std::size_t k = 0; k < order.size(); ++k) {
    const PreparedSegment& s = segments[order[k]];
    const double s_r_max = r_max(s);
    const double s_z_min = std::min(pts[s.a].z, pts[s.b].z);
    const double s_z_max = std::max(pts[s.a].z, pts[s.b].z);
    const Kernel::Segment_2 s2(to_cgal(pts[s.a]), to_cgal(pts[s.b]));
    for (std::size_t m = k + 1; m < order.size() && r_min(segments[order[m]]) <= s_r_max; ++m) {
      const PreparedSegment& t = segments[order[m]];
      if (t.a == s.a || t.a == s.b || t.b == s.a || t.b == s.b) continue;
      if (std::max(pts[t.a].z, pts[t.b].z) < s_z_min || std::min(pts[t.a].z, pts[t.b].z) > s_z_max)
        continue;
      const Kernel::Segment_2 t2(to_cgal(pts[t.a]), to_cgal(pts[t.b]));
      if (!CGAL::do_intersect(s2, t2)) continue;
      Point where = pts[t.a];
      if (auto hit = CGAL::intersection(s2, t2)) {
        if (const auto* p = boost::get<Kernel::Point_2>(&*hit)) where = {p->x(), p->y()};
      }
      const int i = std::min(s.source_segment, t.source_segment);
      const int j = std::max(s.source_segment, t.source_segment);
      fail(pslg, "segments " + std::to_string(i) + " and " + std::to_string(j) +
                     " cross or overlap near " + format_point(where) +
                     "; expected segments that meet only at shared end points "
                     "(self-intersecting boundary or overlapping regions?)");
    }
  }
}

void check_seeds_off_segments(const Pslg& pslg, const std::vector<PreparedSegment>& segments,
                              double tolerance) {
  // Only segments whose boxes hold the seed can hold it: checked in the order of all segments.
  std::vector<Box2> boxes;
  boxes.reserve(segments.size());
  for (const PreparedSegment& s : segments) {
    const Point& a = pslg.points[s.a];
    const Point& b = pslg.points[s.b];
    boxes.push_back({std::min(a.r, b.r) - tolerance, std::min(a.z, b.z) - tolerance,
                     std::max(a.r, b.r) + tolerance, std::max(a.z, b.z) + tolerance});
  }
  const BoxGrid grid(boxes);
  for (std::size_t i = 0; i < pslg.regions.size(); ++i) {
    const RegionSeed& region = pslg.regions[i];
    const Point& p = region.seed;
    for (const int k : grid.candidates({p.r, p.z, p.r, p.z})) {
      const PreparedSegment& s = segments[static_cast<std::size_t>(k)];
      auto [dist_sq, t] = distance_to_segment(region.seed, pslg.points[s.a], pslg.points[s.b]);
      if (dist_sq <= tolerance * tolerance)
        fail(pslg, "the seed point " + format_point(region.seed) + " of region " +
                       std::to_string(i) + " '" + region.name + "' lies on segment " +
                       std::to_string(s.source_segment) +
                       "; expected a point strictly inside the region");
    }
  }
}

}  // namespace

std::string format_number(double value) {
  std::ostringstream out;
  out.precision(9);
  out << value;
  return out.str();
}

std::string format_point(const Point& p) {
  std::ostringstream out;
  out.precision(9);
  out << "(" << p.r << ", " << p.z << ")";
  return out.str();
}

std::string pslg_name(const Pslg& pslg) {
  return pslg.source.empty() ? std::string("geometry") : pslg.source;
}

PreparedPslg prepare_pslg(const Pslg& pslg) {
  check_finite(pslg);
  check_segment_pieces(pslg);
  if (pslg.points.size() < 3 || pslg.segments.size() < 3)
    fail(pslg, "has " + std::to_string(pslg.points.size()) + " points and " +
                   std::to_string(pslg.segments.size()) +
                   " segments; expected at least one closed boundary (3 points, 3 segments)");
  double r_lo = pslg.points[0].r, r_hi = r_lo, z_lo = pslg.points[0].z, z_hi = z_lo;
  for (const Point& p : pslg.points) {
    r_lo = std::min(r_lo, p.r), r_hi = std::max(r_hi, p.r);
    z_lo = std::min(z_lo, p.z), z_hi = std::max(z_hi, p.z);
  }
  PreparedPslg prepared;
  prepared.points = pslg.points;
  prepared.tolerance = kRelativeTolerance * std::max(r_hi - r_lo, z_hi - z_lo);
  const std::vector<int> by_r = sorted_by_r(pslg.points);
  check_distinct_points(pslg, by_r, prepared.tolerance);
  prepared.segments = merge_duplicates(pslg, split_at_points(pslg, by_r, prepared.tolerance));
  check_no_crossings(pslg, prepared.segments);
  check_seeds_off_segments(pslg, prepared.segments, prepared.tolerance);
  return prepared;
}

}  // namespace rheomag::mesh
