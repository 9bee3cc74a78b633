#pragma once
// Test helper: axisymmetric problems made of rectangular regions in (r, z), solved through the
// real path (close domain -> CGAL mesh -> solve).

#include <string>
#include <vector>

#include "case/problem.hpp"

namespace rheomag::test {

/// An axis-aligned rectangle [r0, r1] x [z0, z1] region [m].
struct Rectangle {
  double r0, r1, z0, z1;
  std::string name;
  int material = 0;        ///< index into the problem's materials
  double turns = 0.0;      ///< coil turns (circuit 0) if not 0
  double mesh_size = 0.0;  ///< [m], 0 = automatic
  mesh::GapKind gap = mesh::GapKind::none;
};

/// Problem with the given rectangles (they must not overlap; shared edges are merged by the
/// mesher's PSLG check only if identical, so give disjoint rectangles), one circuit at
/// `current`, materials, and an automatic outer boundary.
inline cases::Problem rectangles_problem(const std::vector<Rectangle>& rectangles,
                                         std::vector<cases::Material> materials, double current,
                                         cases::OuterBoundary outer, int order) {
  using namespace magnetostatics;
  cases::Problem p;
  p.symmetry = cases::Symmetry::axisymmetric;
  p.order = order;
  p.outer = outer;
  p.materials = std::move(materials);
  p.circuits = {{"coil", current}};
  p.geometry.source = "test geometry";
  for (const Rectangle& box : rectangles) {
    const int first = static_cast<int>(p.geometry.points.size());
    p.geometry.points.push_back({box.r0, box.z0});
    p.geometry.points.push_back({box.r1, box.z0});
    p.geometry.points.push_back({box.r1, box.z1});
    p.geometry.points.push_back({box.r0, box.z1});
    for (int k = 0; k < 4; ++k) p.geometry.segments.push_back({first + k, first + (k + 1) % 4});
    mesh::RegionSeed seed;
    seed.seed = {0.5 * (box.r0 + box.r1), 0.5 * (box.z0 + box.z1)};
    seed.name = box.name;
    seed.mesh_size = box.mesh_size;
    seed.gap = box.gap;
    p.geometry.regions.push_back(seed);
    p.regions.push_back({box.material, box.turns != 0.0 ? 0 : -1, box.turns});
  }
  return p;
}

}  // namespace rheomag::test
