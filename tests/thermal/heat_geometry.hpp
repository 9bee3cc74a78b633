#pragma once
// Test helper: axisymmetric bodies of stacked rectangles in (r, z) whose sides carry boundary
// markers, meshed through the real mesher, for the closed-form heat-conduction checks.

#include <string>
#include <vector>

#include "case/problem.hpp"
#include "mesh/mesher.hpp"
#include "thermal/heat_model.hpp"

namespace rheomag::test {

/// One annular (or solid, r0 = 0) ring [r0, r1] x [z0, z1] with its thermal data [m, SI].
struct Ring {
  double r0, r1;
  double conductivity, heat_capacity, source;
};

/// Concentric rings of height `height` in an axisymmetric problem. The outer rim (r = r1 of the
/// last ring) carries boundary marker 0, the two ends (z = 0 and z = height) marker 1.
inline cases::Problem rings_problem(const std::vector<Ring>& rings, double height) {
  cases::Problem p;
  p.symmetry = cases::Symmetry::axisymmetric;
  p.outer = cases::OuterBoundary::none;
  p.boundaries = {{"rim"}, {"ends"}};
  cases::Material body;
  body.name = "body";
  p.materials = {body};
  p.geometry.source = "test rings";
  // Points: bottom row r_0..r_n at z = 0, then the top row at z = height.
  const int n = static_cast<int>(rings.size());
  for (int row = 0; row < 2; ++row) {
    p.geometry.points.push_back({rings.front().r0, row * height});
    for (const Ring& ring : rings) p.geometry.points.push_back({ring.r1, row * height});
  }
  const int top = n + 1;
  for (int i = 0; i < n; ++i) {
    p.geometry.segments.push_back({i, i + 1, 1});              // bottom end
    p.geometry.segments.push_back({top + i, top + i + 1, 1});  // top end
  }
  for (int i = 0; i <= n; ++i)  // vertical lines: the axis (or inner face), interfaces, the rim
    p.geometry.segments.push_back({i, top + i, i == n ? 0 : -1});
  for (int i = 0; i < n; ++i) {
    mesh::RegionSeed seed;
    seed.seed = {0.5 * (rings[i].r0 + rings[i].r1), 0.5 * height};
    seed.name = "ring" + std::to_string(i);
    p.geometry.regions.push_back(seed);
    p.regions.push_back({0});
  }
  return p;
}

/// The HeatModel of rings_problem: rim = `rim`, ends insulated (surface 1).
inline thermal::HeatModel rings_model(const std::vector<Ring>& rings,
                                      const thermal::SurfaceCondition& rim) {
  thermal::HeatModel model;
  model.surfaces = {rim, {"ends", thermal::SurfaceKind::insulated}};
  for (const Ring& ring : rings)
    model.regions.push_back({true, ring.conductivity, ring.heat_capacity, ring.source});
  model.surface_of_region.assign(rings.size(), 0);
  model.surface_of_boundary = {0, 1};
  return model;
}

/// A mesh of `problem` with edges of about `size` metres.
inline mesh::Mesh mesh_of(const cases::Problem& problem, double size, int order) {
  mesh::MeshOptions options;
  options.order = order;
  options.default_size = size;
  return mesh::generate_mesh(problem.geometry, options);
}

}  // namespace rheomag::test
