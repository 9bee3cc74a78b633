// The coarse triangulation of the PSLG with a region on every face (see region_labels.hpp).

#include "mesh/region_labels.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "mesh/quality.hpp"

namespace rheomag::mesh::detail {

namespace {

std::string region_label(const Pslg& pslg, int i) {
  const RegionSeed& seed = pslg.regions[static_cast<std::size_t>(i)];
  return "region " + std::to_string(i) + " '" + seed.name + "'" +
         (seed.where.empty() ? std::string() : " (" + seed.where + ")");
}

}  // namespace

void label_regions(const Pslg& pslg, Cdt& cdt) {
  const std::string name = pslg_name(pslg);
  if (cdt.dimension() < 2)
    throw InputError(name + ": the points are all on one line; expected closed boundaries");
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    f->info().region = kUnlabelled;
  flood_fill(cdt, cdt.infinite_face(), kOutside);

  for (std::size_t i = 0; i < pslg.regions.size(); ++i) {
    const RegionSeed& region = pslg.regions[i];
    Cdt::Face_handle f = cdt.locate(CgalPoint(region.seed.r, region.seed.z));
    const int label = f->info().region;
    if (cdt.is_infinite(f) || label == kOutside) {
      // The default region needs no seed of its own (FEMM's default block label may sit
      // anywhere): it fills the areas no seed reaches.
      if (static_cast<int>(i) == pslg.default_region) continue;
      throw InputError(name + ": the seed point " + format_point(region.seed) + " of " +
                       region_label(pslg, static_cast<int>(i)) +
                       " lies outside every closed boundary; expected a point inside the "
                       "region (is its boundary closed?)");
    }
    if (label >= 0)
      throw InputError(name + ": " + region_label(pslg, label) + " and " +
                       region_label(pslg, static_cast<int>(i)) +
                       " have their seed points in the same enclosed area (near " +
                       format_point(region.seed) +
                       "); expected one seed per area (overlapping regions, or an open "
                       "boundary between them?)");
    flood_fill(cdt, f, static_cast<int>(i));
  }

  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info().region != kUnlabelled) continue;
    if (pslg.default_region < 0) {
      const CgalPoint c =
          CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
      throw InputError(name + ": no region/material for the area near " +
                       format_point({c.x(), c.y()}) +
                       "; expected a region seed (block label) inside every closed area");
    }
    flood_fill(cdt, f, pslg.default_region);
  }
}

std::vector<RegionGeometry> region_geometry(const Cdt& cdt, int region_count) {
  std::vector<RegionGeometry> geometry(static_cast<std::size_t>(region_count));
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const int r = f->info().region;
    if (r < 0) continue;
    RegionGeometry& g = geometry[static_cast<std::size_t>(r)];
    g.area += CGAL::area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    for (int i = 0; i < 3; ++i) {
      if (f->neighbor(i)->info().region == r && !cdt.is_infinite(f->neighbor(i))) continue;
      g.perimeter += std::sqrt(
          CGAL::squared_distance(f->vertex(Cdt::ccw(i))->point(), f->vertex(Cdt::cw(i))->point()));
    }
  }
  for (RegionGeometry& g : geometry) g.thickness = band_thickness(g.area, g.perimeter);
  return geometry;
}

}  // namespace rheomag::mesh::detail
