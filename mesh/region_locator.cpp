// Which region a point lies in (see region_locator.hpp).

#include "mesh/region_locator.hpp"

#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh/region_labels.hpp"

namespace rheomag::mesh::detail {

namespace {

/// A triangulation of at most this many vertices is located in as it is: its walks are short
/// however thin its triangles (the valve of bench_mesh has 117; an arc divided every 0.05 degrees
/// 3600, where refining takes a 0.29 s mesh to 0.19 s).
constexpr std::size_t kRefineAboveVertices = 2000;

/// Refines the faces inside the outer boundary to angles of about 20 degrees (CGAL's refinement
/// needs its domain closed by constraints; the few faces outside are left as they are). It only
/// speeds the walks up, so it stops after a bounded number of steps whatever the geometry.
void refine_for_shape(Cdt& cdt) {
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    f->set_in_domain(f->info().region != kOutside);
  using Criteria = CGAL::Delaunay_mesh_criteria_2<Cdt>;
  CGAL::Delaunay_mesher_2<Cdt, Criteria> mesher(cdt, Criteria(0.125));  // sin^2 of 20.7 deg
  mesher.init(/*domain_specified=*/true);
  const std::size_t most_steps = 50 * cdt.number_of_vertices() + 100000;
  for (std::size_t step = 0; step < most_steps && mesher.try_one_step_refine_mesh(); ++step) {
  }
}

}  // namespace

RegionLocator::RegionLocator(const Cdt& outline, const Pslg& pslg) : cdt_(outline) {
  if (cdt_.number_of_vertices() > kRefineAboveVertices) refine_for_shape(cdt_);
  label_regions(pslg, cdt_);  // anew: refinement reuses face records, moving the copied labels

  // About four vertices per grid cell, 16 to 1024 cells a side.
  double r_lo = std::numeric_limits<double>::infinity(), r_hi = -r_lo, z_lo = r_lo, z_hi = -r_lo;
  for (auto v = cdt_.finite_vertices_begin(); v != cdt_.finite_vertices_end(); ++v) {
    r_lo = std::min(r_lo, v->point().x()), r_hi = std::max(r_hi, v->point().x());
    z_lo = std::min(z_lo, v->point().y()), z_hi = std::max(z_hi, v->point().y());
  }
  const double side = std::clamp(std::sqrt(cdt_.number_of_vertices() / 4.0), 16.0, 1024.0);
  r0_ = r_lo, z0_ = z_lo;
  cell_ = std::max(std::max(r_hi - r_lo, z_hi - z_lo) / side, std::numeric_limits<double>::min());
  columns_ = static_cast<int>((r_hi - r_lo) / cell_) + 1;
  rows_ = static_cast<int>((z_hi - z_lo) / cell_) + 1;
  start_.reserve(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_));
  Cdt::Face_handle hint = cdt_.finite_faces_begin();
  for (int w = 0; w < rows_; ++w)
    for (int c = 0; c < columns_; ++c) {
      // Row by row, each centre located from its neighbour's face: every walk one cell long.
      const int column = w % 2 == 0 ? c : columns_ - 1 - c;
      hint = cdt_.locate(CgalPoint(r0_ + (column + 0.5) * cell_, z0_ + (w + 0.5) * cell_), hint);
      if (cdt_.is_infinite(hint)) hint = hint->neighbor(hint->index(cdt_.infinite_vertex()));
      start_.push_back(hint);
    }
  // start_ was filled in a serpentine: put each row back in column order.
  for (int w = 1; w < rows_; w += 2)
    std::reverse(start_.begin() + static_cast<std::ptrdiff_t>(w) * columns_,
                 start_.begin() + static_cast<std::ptrdiff_t>(w + 1) * columns_);
}

int RegionLocator::region_at(const CgalPoint& p) const {
  const int c = std::clamp(static_cast<int>(std::floor((p.x() - r0_) / cell_)), 0, columns_ - 1);
  const int w = std::clamp(static_cast<int>(std::floor((p.y() - z0_) / cell_)), 0, rows_ - 1);
  const std::size_t cell = static_cast<std::size_t>(w) * static_cast<std::size_t>(columns_) +
                           static_cast<std::size_t>(c);
  last_face_ = cdt_.locate(
      p, cell == last_cell_ && last_face_ != Cdt::Face_handle() ? last_face_ : start_[cell]);
  last_cell_ = cell;
  return cdt_.is_infinite(last_face_) ? kOutside : last_face_->info().region;
}

}  // namespace rheomag::mesh::detail
