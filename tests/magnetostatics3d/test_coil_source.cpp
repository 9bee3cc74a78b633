// The coil's source field T_z(r, z) (curl T = J), which the 3D coil loads integrate, against a
// direct sum over every coil triangle of the meridian mesh, written here independently (the
// triangle's vertices sorted by height). circuit_source_tz looks a height up in z slabs of the
// coil's triangles; a triangle missing from a slab would show as a lost chord.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "magnetostatics/domain.hpp"
#include "magnetostatics3d/coil_source.hpp"
#include "mesh/mesher.hpp"
#include "mesh/triangle.hpp"

namespace rheomag::magnetostatics3d {
namespace {

const bool kLaterSectionsRegistered = cases::register_case_section("valve") &&
                                      cases::register_case_section("damper") &&
                                      cases::register_case_section("fluid");

/// Length of the part of the horizontal line at height z inside triangle v at radius > r.
double chord_right_of(std::array<mesh::Point, 3> v, double r, double z) {
  std::sort(v.begin(), v.end(),
            [](const mesh::Point& a, const mesh::Point& b) { return a.z < b.z; });
  if (z < v[0].z || z > v[2].z || v[0].z == v[2].z) return 0.0;
  auto at = [z](const mesh::Point& a, const mesh::Point& b) {
    return a.r + (b.r - a.r) * (z - a.z) / (b.z - a.z);
  };
  const double x1 = at(v[0], v[2]);
  double x2;
  if (z == v[0].z && v[1].z == v[0].z) {
    x2 = v[1].r;  // the line runs along the bottom edge
  } else if (z == v[2].z && v[1].z == v[2].z) {
    x2 = v[1].r;  // along the top edge
  } else {
    x2 = z <= v[1].z ? at(v[0], v[1]) : at(v[1], v[2]);
  }
  const double lo = std::min(x1, x2), hi = std::max(x1, x2);
  return std::max(0.0, hi - std::max(r, lo));
}

// Reference: sum over the coil triangles of (turns / region area) x chord_right_of. Tolerance
// 1e-12 of the largest T_z (the two differ only in rounding). Points: random ones around the
// coil and ones at every vertex height of a coil triangle (the slab boundaries and the
// horizontal edges, where T_z jumps).
TEST(CoilSource, SourceFieldEqualsTheSumOverEveryCoilTriangle) {
  const std::string path = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";
  const cases::Problem closed =
      magnetostatics::close_domain(cases::parse_case(cases::read_input_file(path), path).problem);
  mesh::MeshOptions options;
  options.order = 1;
  const mesh::Mesh meridian = mesh::generate_mesh(closed.geometry, options);
  const auto tz = circuit_source_tz(closed, meridian);
  ASSERT_EQ(tz.size(), closed.circuits.size());

  std::vector<double> area(closed.regions.size(), 0.0);
  for (std::size_t e = 0; e < meridian.triangles.size(); ++e) {
    const auto& t = meridian.triangles[e];
    area[meridian.region[e]] +=
        mesh::triangle_area(meridian.nodes[t[0]], meridian.nodes[t[1]], meridian.nodes[t[2]]);
  }
  std::vector<std::array<mesh::Point, 3>> coil;
  std::vector<double> density;
  double r_lo = INFINITY, r_hi = -INFINITY, z_lo = INFINITY, z_hi = -INFINITY;
  for (std::size_t e = 0; e < meridian.triangles.size(); ++e) {
    const cases::RegionData& rd = closed.regions[meridian.region[e]];
    if (rd.circuit != 0 || rd.turns == 0.0) continue;
    const auto& t = meridian.triangles[e];
    coil.push_back({meridian.nodes[t[0]], meridian.nodes[t[1]], meridian.nodes[t[2]]});
    density.push_back(rd.turns / area[meridian.region[e]]);
    for (const mesh::Point& p : coil.back()) {
      r_lo = std::min(r_lo, p.r), r_hi = std::max(r_hi, p.r);
      z_lo = std::min(z_lo, p.z), z_hi = std::max(z_hi, p.z);
    }
  }
  ASSERT_GT(coil.size(), 40u);  // many slabs, most triangles in one or two

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.1, 1.1);
  std::vector<std::array<double, 2>> points;
  for (int k = 0; k < 4000; ++k)
    points.push_back({r_lo + u(rng) * (r_hi - r_lo), z_lo + u(rng) * (z_hi - z_lo)});
  for (const auto& tri : coil)
    for (const mesh::Point& p : tri) points.push_back({r_lo + u(rng) * (r_hi - r_lo), p.z});

  double largest = 0.0, worst = 0.0;
  int inside = 0;
  for (const auto& [r, z] : points) {
    double reference = 0.0;
    for (std::size_t i = 0; i < coil.size(); ++i)
      reference += density[i] * chord_right_of(coil[i], r, z);
    largest = std::max(largest, std::abs(reference));
    worst = std::max(worst, std::abs(tz[0](r, z) - reference));
    inside += reference > 0.0;
  }
  EXPECT_GT(inside, 2000);  // most points see some of the coil
  EXPECT_GT(largest, 0.0);
  EXPECT_LE(worst, 1e-12 * largest);
}

}  // namespace
}  // namespace rheomag::magnetostatics3d
