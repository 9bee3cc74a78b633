#include "magnetostatics/circuit_currents.hpp"

#include "mesh/triangle.hpp"

namespace rheomag::magnetostatics {

namespace {

/// Electrical conductivity of a region's material [S/m] (0 when the material states none).
double region_conductivity(const cases::Problem& problem, int region) {
  const int material = problem.regions[region].material;
  if (material < 0 || material >= static_cast<int>(problem.materials.size())) return 0.0;
  return problem.materials[material].conductivity.value_or(0.0);
}

/// Spreads the current of one group of regions (FEMM's "parallel circuit"); `turns` scales the
/// circuit's current to the group's (a series label's turns, 1 for a parallel circuit).
void spread_group(const cases::Problem& problem, const std::vector<int>& group, double turns,
                  const std::vector<double>& area, const std::vector<double>& integral_g,
                  std::vector<RegionCurrent>& out) {
  double total_area = 0.0, fixed_current = 0.0, conductance = 0.0;
  for (int r : group) {
    total_area += area[r];
    fixed_current += problem.regions[r].current_density * area[r];
    if (problem.regions[r].solid_conductor)
      conductance += region_conductivity(problem, r) * integral_g[r];
  }
  const bool axisymmetric = problem.symmetry == cases::Symmetry::axisymmetric;
  for (int r : group) {
    RegionCurrent& c = out[r];
    if (conductance > 0.0) {
      // A voltage drives the group: J = sigma E; every conducting region of the group carries
      // current (a winding too, as in FEMM, though only solid conductors count in D).
      const double share = region_conductivity(problem, r) / conductance;
      c = {turns * share, -fixed_current * share, axisymmetric};
    } else if (total_area > 0.0) {
      c = {turns / total_area, -fixed_current / total_area, false};
    }
  }
}

}  // namespace

std::vector<RegionCurrent> circuit_currents(const cases::Problem& problem, const mesh::Mesh& mesh,
                                            const std::vector<double>& area) {
  const int regions = static_cast<int>(problem.regions.size());
  std::vector<RegionCurrent> out(regions);
  // integral of g = 1/r over each region (centroid rule, as FEMM), or its area when planar.
  std::vector<double> integral_g = area;
  if (problem.symmetry == cases::Symmetry::axisymmetric) {
    integral_g.assign(regions, 0.0);
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
      const auto& t = mesh.triangles[e];
      const mesh::Point a = mesh.nodes[t[0]], b = mesh.nodes[t[1]], c = mesh.nodes[t[2]];
      integral_g[mesh.region[e]] +=
          mesh::triangle_area(a, b, c) / mesh::triangle_centroid(a, b, c).r;
    }
  }
  for (int c = 0; c < static_cast<int>(problem.circuits.size()); ++c) {
    std::vector<int> members;
    for (int r = 0; r < regions; ++r)
      if (problem.regions[r].circuit == c) members.push_back(r);
    if (problem.circuits[c].parallel) {
      spread_group(problem, members, 1.0, area, integral_g, out);
    } else {
      for (int r : members) {
        if (problem.regions[r].turns == 0.0) continue;
        spread_group(problem, {r}, problem.regions[r].turns, area, integral_g, out);
      }
    }
  }
  return out;
}

}  // namespace rheomag::magnetostatics
