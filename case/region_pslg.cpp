// Region outlines -> PSLG (merged points, split and deduplicated segments, seeds).

#include "case/region_pslg.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "case/geometry_check.hpp"
#include "core/error.hpp"
#include "mesh/box_grid.hpp"

namespace rheomag::cases {
namespace {

using mesh::Point;

/// The merged points of the outlines: a point within `tolerance` (in r and in z) of an earlier
/// one is that point. Filed by cells of the tolerance's size, so a merge looks at 9 cells.
class MergedPoints {
 public:
  MergedPoints(std::vector<Point>& points, double tolerance)
      : points_(points), cell_(tolerance > 0.0 ? tolerance : 1.0), tolerance_(tolerance) {}

  /// Index of `p` in the points, appending it when no point lies within the tolerance (the
  /// earliest such point when several do).
  int add(const Point& p) {
    const long long cr = cell_of(p.r), cz = cell_of(p.z);
    int found = -1;
    for (long long dr = -1; dr <= 1; ++dr)
      for (long long dz = -1; dz <= 1; ++dz) {
        const auto it = cells_.find({cr + dr, cz + dz});
        if (it == cells_.end()) continue;
        for (int i : it->second) {
          const Point& q = points_[static_cast<std::size_t>(i)];
          if (std::abs(q.r - p.r) <= tolerance_ && std::abs(q.z - p.z) <= tolerance_ &&
              (found < 0 || i < found))
            found = i;
        }
      }
    if (found >= 0) return found;
    points_.push_back(p);
    const int index = static_cast<int>(points_.size()) - 1;
    cells_[{cr, cz}].push_back(index);
    return index;
  }

 private:
  long long cell_of(double x) const {
    const double c = std::floor(x / cell_);
    return std::isfinite(c) ? static_cast<long long>(std::clamp(c, -4e18, 4e18)) : 0;
  }
  std::vector<Point>& points_;
  double cell_, tolerance_;
  std::map<std::pair<long long, long long>, std::vector<int>> cells_;
};

/// The bounding box of `outline`, grown by `margin` on every side.
mesh::Box2 box_of(const std::vector<Point>& outline, double margin) {
  mesh::Box2 b{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const Point& p : outline) {
    b.r_lo = std::min(b.r_lo, p.r), b.r_hi = std::max(b.r_hi, p.r);
    b.z_lo = std::min(b.z_lo, p.z), b.z_hi = std::max(b.z_hi, p.z);
  }
  b.r_lo -= margin, b.z_lo -= margin, b.r_hi += margin, b.z_hi += margin;
  return b;
}

}  // namespace

double outline_tolerance(const std::vector<RegionOutline>& regions) {
  double extent = 0.0;
  for (const RegionOutline& region : regions)
    for (const Point& p : region.outline) extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
  return std::max(extent, 1e-6) * 1e-9;
}

mesh::Pslg outlines_to_pslg(const std::vector<RegionOutline>& regions, const std::string& source,
                            const std::string& background) {
  if (regions.empty()) throw InputError(source + ": no regions defined");
  const double tolerance = outline_tolerance(regions);
  for (const RegionOutline& region : regions) check_simple_polygon(region, tolerance);
  // Only regions whose boxes touch can overlap: pairs in the same order as all pairs would be.
  std::vector<mesh::Box2> region_boxes;
  for (const RegionOutline& region : regions)
    region_boxes.push_back(box_of(region.outline, tolerance));
  const mesh::BoxGrid region_grid(region_boxes);
  for (std::size_t i = 0; i < regions.size(); ++i)
    for (const int j : region_grid.candidates(region_boxes[i]))
      if (static_cast<std::size_t>(j) > i) check_disjoint(regions[i], regions[j], tolerance);

  mesh::Pslg pslg;
  pslg.source = source;
  MergedPoints merged(pslg.points, tolerance);
  for (const RegionOutline& region : regions)
    for (const Point& p : region.outline) merged.add(p);
  std::vector<mesh::Box2> point_boxes;
  point_boxes.reserve(pslg.points.size());
  for (const Point& p : pslg.points) point_boxes.push_back({p.r, p.z, p.r, p.z});
  const mesh::BoxGrid point_grid(point_boxes);

  std::set<std::pair<int, int>> seen;
  for (const RegionOutline& region : regions) {
    const std::size_t n = region.outline.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point a = region.outline[i];
      const Point b = region.outline[(i + 1) % n];
      const double dr = b.r - a.r, dz = b.z - a.z;
      const double length2 = dr * dr + dz * dz;
      // Parameters of every PSLG point lying on this edge, ends included.
      std::vector<std::pair<double, int>> on_edge;
      for (const int k : point_grid.candidates(box_of({a, b}, 2.0 * tolerance))) {
        const Point& p = pslg.points[static_cast<std::size_t>(k)];
        const double t = ((p.r - a.r) * dr + (p.z - a.z) * dz) / length2;
        if (t < -1e-12 || t > 1.0 + 1e-12) continue;
        if (std::hypot(p.r - (a.r + t * dr), p.z - (a.z + t * dz)) > tolerance) continue;
        on_edge.emplace_back(t, k);
      }
      std::sort(on_edge.begin(), on_edge.end());
      for (std::size_t k = 0; k + 1 < on_edge.size(); ++k) {
        const int u = on_edge[k].second, v = on_edge[k + 1].second;
        if (u == v) continue;
        if (seen.insert({std::min(u, v), std::max(u, v)}).second)
          pslg.segments.push_back({u, v, -1, 0.0});
      }
    }
  }

  double r_max = -HUGE_VAL, z_min = HUGE_VAL, z_max = -HUGE_VAL, r_min = HUGE_VAL;
  for (const RegionOutline& region : regions) {
    mesh::RegionSeed seed;
    seed.seed = interior_point(region.outline);
    seed.name = region.name;
    seed.mesh_size = region.mesh_size;
    seed.gap = region.gap;
    pslg.regions.push_back(seed);
    for (const Point& p : region.outline) {
      r_min = std::min(r_min, p.r);
      r_max = std::max(r_max, p.r);
      z_min = std::min(z_min, p.z);
      z_max = std::max(z_max, p.z);
    }
  }
  if (!background.empty()) {
    mesh::RegionSeed air;
    const double extent = std::max(r_max - r_min, z_max - z_min);
    air.seed = {r_max + 0.25 * extent, 0.5 * (z_min + z_max)};
    air.name = background;
    pslg.default_region = static_cast<int>(pslg.regions.size());
    pslg.regions.push_back(air);
  }
  return pslg;
}

}  // namespace rheomag::cases
