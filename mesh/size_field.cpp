// The target element edge length at any point of the domain (see size_field.hpp).

#include "mesh/size_field.hpp"

#include "mesh/straight_runs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rheomag::mesh::detail {

namespace {

/// Number of grid cells along the longer side of the bounding box.
constexpr int kSizeGridCells = 64;

}  // namespace

SizeField::SizeField(const Cdt& outline, const Pslg& pslg, std::vector<double> region_size,
                     double grading)
    : regions_(outline, pslg), region_size_(std::move(region_size)), grading_(grading) {
  double largest = 0.0;
  for (double h : region_size_)
    if (std::isfinite(h)) largest = std::max(largest, h);
  if (grading_ <= 0.0) return;

  auto size_of = [&](int region) {
    return region >= 0 ? region_size_[static_cast<std::size_t>(region)]
                       : std::numeric_limits<double>::infinity();
  };
  std::vector<SizedEdge> edges;
  for (auto e = outline.finite_edges_begin(); e != outline.finite_edges_end(); ++e) {
    if (!outline.is_constrained(*e)) continue;
    const auto [f, i] = *e;
    double size = std::min(size_of(f->info().region), size_of(f->neighbor(i)->info().region));
    if (f->info().max_length[i] > 0.0) size = std::min(size, f->info().max_length[i]);
    const CgalPoint& a = f->vertex(Cdt::ccw(i))->point();
    const CgalPoint& b = f->vertex(Cdt::cw(i))->point();
    if (size < largest) edges.push_back({{a.x(), a.y()}, {b.x(), b.y()}, size});
  }
  // A segment cut into many pieces is one source: the cells beside it would otherwise hold one
  // source per piece, and every size query there would scan them all.
  for (const SizedEdge& run : merge_straight_runs(edges))
    sources_.push_back({CgalPoint(run.a[0], run.a[1]), CgalPoint(run.b[0], run.b[1]), run.size});

  double r_lo = std::numeric_limits<double>::infinity(), r_hi = -r_lo, z_lo = r_lo, z_hi = -r_lo;
  for (auto v = outline.finite_vertices_begin(); v != outline.finite_vertices_end(); ++v) {
    r_lo = std::min(r_lo, v->point().x()), r_hi = std::max(r_hi, v->point().x());
    z_lo = std::min(z_lo, v->point().y()), z_hi = std::max(z_hi, v->point().y());
  }
  r0_ = r_lo, z0_ = z_lo;
  cell_ = std::max(r_hi - r_lo, z_hi - z_lo) / kSizeGridCells;
  columns_ = static_cast<int>((r_hi - r_lo) / cell_) + 1;
  rows_ = static_cast<int>((z_hi - z_lo) / cell_) + 1;
  buckets_.assign(static_cast<std::size_t>(columns_ * rows_), {});
  for (std::size_t s = 0; s < sources_.size(); ++s)
    add_to_grid(static_cast<int>(s), (largest - sources_[s].size) / grading_);
}

void SizeField::add_to_grid(int source, double reach) {
  const Source& s = sources_[static_cast<std::size_t>(source)];
  auto column = [&](double r) {
    return std::clamp(static_cast<int>(std::floor((r - r0_) / cell_)), 0, columns_ - 1);
  };
  auto row = [&](double z) {
    return std::clamp(static_cast<int>(std::floor((z - z0_) / cell_)), 0, rows_ - 1);
  };
  const int c0 = column(std::min(s.a.x(), s.b.x()) - reach);
  const int c1 = column(std::max(s.a.x(), s.b.x()) + reach);
  const int w0 = row(std::min(s.a.y(), s.b.y()) - reach);
  const int w1 = row(std::max(s.a.y(), s.b.y()) + reach);
  for (int w = w0; w <= w1; ++w)
    for (int c = c0; c <= c1; ++c)
      buckets_[static_cast<std::size_t>(w * columns_ + c)].push_back(source);
}

int SizeField::region_at(const CgalPoint& p) const {
  return regions_.region_at(p);
}

double SizeField::at(const CgalPoint& p) const {
  const int region = region_at(p);
  double h = region >= 0 ? region_size_[static_cast<std::size_t>(region)]
                         : std::numeric_limits<double>::infinity();
  if (buckets_.empty()) return h;
  const int c = std::clamp(static_cast<int>(std::floor((p.x() - r0_) / cell_)), 0, columns_ - 1);
  const int w = std::clamp(static_cast<int>(std::floor((p.y() - z0_) / cell_)), 0, rows_ - 1);
  for (int s : buckets_[static_cast<std::size_t>(w * columns_ + c)]) {
    const Source& source = sources_[static_cast<std::size_t>(s)];
    if (source.size >= h) continue;
    h = std::min(h, source.size + grading_ * segment_distance(p, source.a, source.b));
  }
  return h;
}

}  // namespace rheomag::mesh::detail
