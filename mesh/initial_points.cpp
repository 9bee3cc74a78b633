// A triangular lattice of starting points (see initial_points.hpp).

#include "mesh/initial_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rheomag::mesh::detail {

namespace {

/// Fraction of the local spacing that a lattice point keeps from every constrained edge.
constexpr double kClearance = 0.45;
/// Lattice spacing as a fraction of the target edge length.
constexpr double kSpacing = 0.95;
/// Number of grid cells along the longer side of the bounding box.
constexpr int kConstraintGridCells = 64;

/// Constrained edges of the coarse triangulation bucketed on a uniform grid, for "is any
/// constraint closer than d to p" queries.
class ConstraintGrid {
 public:
  explicit ConstraintGrid(const Cdt& cdt) {
    double r_hi = -std::numeric_limits<double>::infinity(), z_hi = r_hi;
    r0_ = z0_ = -r_hi;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
      r0_ = std::min(r0_, v->point().x()), r_hi = std::max(r_hi, v->point().x());
      z0_ = std::min(z0_, v->point().y()), z_hi = std::max(z_hi, v->point().y());
    }
    cell_ = std::max(r_hi - r0_, z_hi - z0_) / kConstraintGridCells;
    columns_ = static_cast<int>((r_hi - r0_) / cell_) + 1;
    rows_ = static_cast<int>((z_hi - z0_) / cell_) + 1;
    buckets_.assign(static_cast<std::size_t>(columns_ * rows_), {});
    for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
      if (!cdt.is_constrained(*e)) continue;
      const auto [f, i] = *e;
      add(f->vertex(Cdt::ccw(i))->point(), f->vertex(Cdt::cw(i))->point());
    }
    // Input points not on any segment (FEMM allows them) are kept clear of as well.
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      add(v->point(), v->point());
  }

  /// Adds the segment ab (a point when a == b).
  void add(const CgalPoint& a, const CgalPoint& b) {
    const int id = static_cast<int>(edges_.size());
    edges_.emplace_back(a, b);
    for (int w = row(std::min(a.y(), b.y())); w <= row(std::max(a.y(), b.y())); ++w)
      for (int c = column(std::min(a.x(), b.x())); c <= column(std::max(a.x(), b.x())); ++c)
        buckets_[static_cast<std::size_t>(w * columns_ + c)].push_back(id);
  }

  /// True when a constrained edge or an input point is closer than d to p.
  bool any_within(const CgalPoint& p, double d) const {
    for (int w = row(p.y() - d); w <= row(p.y() + d); ++w)
      for (int c = column(p.x() - d); c <= column(p.x() + d); ++c)
        for (int id : buckets_[static_cast<std::size_t>(w * columns_ + c)])
          if (segment_distance(p, edges_[id].first, edges_[id].second) < d) return true;
    return false;
  }

 private:
  int column(double r) const {
    return std::clamp(static_cast<int>(std::floor((r - r0_) / cell_)), 0, columns_ - 1);
  }
  int row(double z) const {
    return std::clamp(static_cast<int>(std::floor((z - z0_) / cell_)), 0, rows_ - 1);
  }

  double r0_ = 0.0, z0_ = 0.0, cell_ = 1.0;
  int columns_ = 1, rows_ = 1;
  std::vector<std::pair<CgalPoint, CgalPoint>> edges_;
  std::vector<std::vector<int>> buckets_;
};

}  // namespace

std::vector<CgalPoint> lattice_points(const Cdt& coarse, const std::vector<double>& region_size,
                                      const SizeField& field) {
  const ConstraintGrid constraints(coarse);
  std::vector<CgalPoint> points;
  for (auto f = coarse.finite_faces_begin(); f != coarse.finite_faces_end(); ++f) {
    const int region = f->info().region;
    if (region < 0) continue;
    const double target = region_size[static_cast<std::size_t>(region)];
    if (!std::isfinite(target) || target <= 0.0) continue;
    // Slightly below the target, so rounding never makes a lattice triangle "too large".
    const double h = kSpacing * target;
    const CgalPoint& a = f->vertex(0)->point();
    const CgalPoint& b = f->vertex(1)->point();
    const CgalPoint& c = f->vertex(2)->point();
    // Lattice anchored at the origin, so faces of one region share it: rows dz apart, every
    // other row shifted by h/2 (equilateral triangles of side h).
    const double dz = h * std::sqrt(3.0) / 2.0;
    const long row_lo = static_cast<long>(std::floor(std::min({a.y(), b.y(), c.y()}) / dz));
    const long row_hi = static_cast<long>(std::ceil(std::max({a.y(), b.y(), c.y()}) / dz));
    const double r_lo = std::min({a.x(), b.x(), c.x()}), r_hi = std::max({a.x(), b.x(), c.x()});
    for (long j = row_lo; j <= row_hi; ++j) {
      const double z = static_cast<double>(j) * dz;
      const double shift = (j % 2 != 0) ? 0.5 * h : 0.0;
      const long col_lo = static_cast<long>(std::floor((r_lo - shift) / h));
      const long col_hi = static_cast<long>(std::ceil((r_hi - shift) / h));
      for (long i = col_lo; i <= col_hi; ++i) {
        const CgalPoint p(static_cast<double>(i) * h + shift, z);
        if (CGAL::orientation(a, b, p) != CGAL::LEFT_TURN ||
            CGAL::orientation(b, c, p) != CGAL::LEFT_TURN ||
            CGAL::orientation(c, a, p) != CGAL::LEFT_TURN)
          continue;  // not strictly inside this face
        if (field.at(p) < 0.999 * target || constraints.any_within(p, kClearance * h)) continue;
        points.push_back(p);
      }
    }
  }
  return points;
}

}  // namespace rheomag::mesh::detail
