// Region outlines -> PSLG (merged points, split and deduplicated segments, seeds).

#include "case/region_pslg.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "case/geometry_check.hpp"
#include "core/error.hpp"

namespace rheomag::cases {
namespace {

using mesh::Point;

/// Index of `p` in `points`, appending it when no point lies within `tolerance`.
int add_point(std::vector<Point>& points, const Point& p, double tolerance) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (std::abs(points[i].r - p.r) <= tolerance && std::abs(points[i].z - p.z) <= tolerance)
      return static_cast<int>(i);
  points.push_back(p);
  return static_cast<int>(points.size()) - 1;
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
  for (std::size_t i = 0; i < regions.size(); ++i)
    for (std::size_t j = i + 1; j < regions.size(); ++j)
      check_disjoint(regions[i], regions[j], tolerance);

  mesh::Pslg pslg;
  pslg.source = source;
  for (const RegionOutline& region : regions)
    for (const Point& p : region.outline) add_point(pslg.points, p, tolerance);

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
      for (std::size_t k = 0; k < pslg.points.size(); ++k) {
        const Point& p = pslg.points[k];
        const double t = ((p.r - a.r) * dr + (p.z - a.z) * dz) / length2;
        if (t < -1e-12 || t > 1.0 + 1e-12) continue;
        if (std::hypot(p.r - (a.r + t * dr), p.z - (a.z + t * dz)) > tolerance) continue;
        on_edge.emplace_back(t, static_cast<int>(k));
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
