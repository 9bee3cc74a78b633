// Which enclosed area of a PSLG each region seed lies in (see seed_areas.hpp).

#include "mesh/seed_areas.hpp"

#include "mesh/cdt.hpp"
#include "mesh/cdt_insert.hpp"
#include "mesh/pslg_check.hpp"

namespace rheomag::mesh {

std::vector<int> seed_areas(const Pslg& pslg) {
  detail::Cdt cdt;
  detail::insert_pslg(prepare_pslg(pslg), cdt);
  std::vector<int> area(pslg.regions.size(), -1);
  if (cdt.dimension() < 2) return area;
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    f->info().region = detail::kUnlabelled;
  detail::flood_fill(cdt, cdt.infinite_face(), detail::kOutside);
  int areas = 0;
  for (std::size_t i = 0; i < pslg.regions.size(); ++i) {
    const Point& p = pslg.regions[i].seed;
    detail::Cdt::Face_handle f = cdt.locate(detail::CgalPoint(p.r, p.z));
    if (cdt.is_infinite(f) || f->info().region == detail::kOutside) continue;
    if (f->info().region == detail::kUnlabelled) detail::flood_fill(cdt, f, areas++);
    area[i] = f->info().region;
  }
  return area;
}

}  // namespace rheomag::mesh
