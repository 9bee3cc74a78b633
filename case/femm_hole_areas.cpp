// FEMM's rule for an area that holds a <No Mesh> label and other labels (see femm_hole_areas.hpp).

#include "case/femm_hole_areas.hpp"

#include <map>
#include <string>
#include <vector>

#include "case/toml_section.hpp"
#include "mesh/seed_areas.hpp"

namespace rheomag::cases {

void drop_labels_in_hole_areas(Problem& problem) {
  std::vector<mesh::RegionSeed>& seeds = problem.geometry.regions;
  bool any_hole = false;
  for (const mesh::RegionSeed& s : seeds) any_hole = any_hole || s.hole;
  if (!any_hole || seeds.size() < 2) return;
  const std::vector<int> area = mesh::seed_areas(problem.geometry);
  std::map<int, std::size_t> hole_of_area;  // area -> its first hole seed
  for (std::size_t i = 0; i < seeds.size(); ++i)
    if (seeds[i].hole && area[i] >= 0 && !hole_of_area.count(area[i])) hole_of_area[area[i]] = i;
  std::vector<bool> drop(seeds.size(), false);
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    const auto hole = area[i] >= 0 ? hole_of_area.find(area[i]) : hole_of_area.end();
    if (hole == hole_of_area.end() || hole->second == i) continue;
    if (static_cast<int>(i) == problem.geometry.default_region) continue;
    drop[i] = true;
    if (seeds[i].hole) continue;  // a second hole in a hole's area changes nothing
    const mesh::RegionSeed& h = seeds[hole->second];
    // "model.fem:12" -> "line 12" when both labels are in one file.
    const std::size_t colon = h.where.rfind(':');
    const bool same_file = colon != std::string::npos &&
                           seeds[i].where.compare(0, colon + 1, h.where, 0, colon + 1) == 0;
    const std::string hole_where = same_file ? "line " + h.where.substr(colon + 1) : h.where;
    const RegionData& data = problem.regions[i];
    std::string coil;
    if (data.circuit >= 0)
      coil = "; its " + format_number(data.turns) + " turn(s) of circuit '" +
             problem.circuits[static_cast<std::size_t>(data.circuit)].name +
             "' are not in the model";
    problem.warnings.push_back(
        seeds[i].where + ": block label '" + seeds[i].name + "' lies in the area of the " +
        (h.name == "hole" ? std::string("hole") : std::string("<No Mesh> label")) + " at " +
        hole_where +
        "; FEMM leaves that area unmeshed (its mesher removes the holes before it gives the "
        "areas their blocks), and so does rheomag" +
        coil + ". Remove one of the two labels to say which is meant");
  }
  std::vector<mesh::RegionSeed> kept_seeds;
  std::vector<RegionData> kept_regions;
  int default_region = -1;
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    if (drop[i]) continue;
    if (static_cast<int>(i) == problem.geometry.default_region)
      default_region = static_cast<int>(kept_seeds.size());
    kept_seeds.push_back(seeds[i]);
    kept_regions.push_back(problem.regions[i]);
  }
  seeds = std::move(kept_seeds);
  problem.regions = std::move(kept_regions);
  problem.geometry.default_region = default_region;
}

}  // namespace rheomag::cases
