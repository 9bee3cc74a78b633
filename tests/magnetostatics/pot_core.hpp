#pragma once
// Test helper: an axisymmetric pot core (iron shell around a coil, air gap in the centre post)
// on a structured mesh. Dimensions in mm: post r < 5, coil 6 < r < 14 and |z| < 8, wall
// 15 < r < 20, plates 10 < |z| < 15, gap |z| < g/2 in the post; A = 0 on the outside surface.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "case/problem.hpp"
#include "tests/magnetostatics/structured_mesh.hpp"

namespace rheomag::test {

/// Region indices of the pot core.
enum PotCoreRegion { kIron = 0, kGap = 1, kCoil = 2, kWindow = 3 };

/// Dimensions of the pot core [m].
struct PotCore {
  double post = 5e-3, coil_inner = 6e-3, coil_outer = 14e-3, wall_inner = 15e-3, wall_outer = 20e-3;
  double coil_half = 8e-3, window_half = 10e-3, outer_half = 15e-3, gap = 1e-3;
};

/// The problem: iron `iron` (linear or B-H), one circuit with `turns` turns at `current`.
inline cases::Problem pot_core_problem(const cases::Material& iron, double turns, double current,
                                       int order) {
  using namespace magnetostatics;
  cases::Problem p;
  p.symmetry = cases::Symmetry::axisymmetric;
  p.order = order;
  p.outer = cases::OuterBoundary::none;
  p.geometry.source = "pot core (test)";
  p.geometry.regions = {{{10e-3, 12e-3}, "iron"},
                        {{2e-3, 0.0}, "gap", 0.0, mesh::GapKind::radial},
                        {{10e-3, 0.0}, "coil"},
                        {{14.5e-3, 9e-3}, "window"}};
  p.materials = {iron, {"air", 1.0, {}, 0.0, "vacuum"}, {"copper", 1.0, {}, 5.8e7, "nonmagnetic"}};
  p.regions = {{0, -1, 0.0}, {1, -1, 0.0}, {2, 0, turns}, {1, -1, 0.0}};
  p.circuits = {{"coil", current}};
  p.boundaries = {{"outside A = 0", cases::BoundaryKind::prescribed_a, 0.0, 0.0, 0.0}};
  return p;
}

/// Structured mesh with about `per_mm` cells per millimetre (at least 4 across the gap).
inline mesh::Mesh pot_core_mesh(const PotCore& c, double per_mm, int order) {
  auto cells = [per_mm](double a, double b) {
    return std::max(2, static_cast<int>(std::ceil((b - a) * 1e3 * per_mm)));
  };
  auto span = [&](std::vector<double> breaks) {
    std::vector<double> x;
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
      int n = cells(breaks[k], breaks[k + 1]);
      if (breaks[k + 1] - breaks[k] <= c.gap + 1e-12) n = std::max(n, 4);
      x = join(x, uniform(breaks[k], breaks[k + 1], n));
    }
    return x;
  };
  const auto r = span({0.0, c.post, c.coil_inner, c.coil_outer, c.wall_inner, c.wall_outer});
  const auto z = span({-c.outer_half, -c.window_half, -c.coil_half, -0.5 * c.gap, 0.5 * c.gap,
                       c.coil_half, c.window_half, c.outer_half});
  auto region = [c](double rr, double zz) {
    const double az = std::abs(zz);
    if (az > c.window_half || rr > c.wall_inner) return static_cast<int>(kIron);
    if (rr < c.post) return static_cast<int>(az < 0.5 * c.gap ? kGap : kIron);
    if (rr > c.coil_inner && rr < c.coil_outer && az < c.coil_half) return static_cast<int>(kCoil);
    return static_cast<int>(kWindow);
  };
  return structured_mesh(r, z, order, region, {-1, 0, 0, 0});
}

}  // namespace rheomag::test
