#include "magnetostatics/domain.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <sstream>
#include <utility>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace rheomag::magnetostatics {
namespace {

int air_material(cases::Problem& p) {
  for (std::size_t m = 0; m < p.materials.size(); ++m) {
    if (p.materials[m].name == "air" && p.materials[m].bh.empty()) return static_cast<int>(m);
  }
  cases::Material air;
  air.name = "air";
  air.mu_r = 1.0;
  air.conductivity = 0.0;
  air.source = "vacuum permeability (air: mu_r - 1 ~ 4e-7)";
  p.materials.push_back(air);
  return static_cast<int>(p.materials.size()) - 1;
}

}  // namespace

cases::Problem close_domain(const cases::Problem& problem) {
  cases::Problem p = problem;
  if (p.outer == cases::OuterBoundary::none) return p;
  auto& g = p.geometry;
  if (g.points.empty()) throw InputError(g.source + ": the geometry has no points");
  if (!std::isfinite(p.outer_radius_factor) || p.outer_radius_factor <= 1.0) {
    std::ostringstream msg;
    msg << g.source << ": outer_radius_factor = " << p.outer_radius_factor
        << "; expected a number > 1";
    throw InputError(msg.str());
  }
  const bool axisymmetric = p.symmetry == cases::Symmetry::axisymmetric;
  double r_min = g.points[0].r, r_max = r_min, z_min = g.points[0].z, z_max = z_min;
  for (const mesh::Point& q : g.points) {
    r_min = std::min(r_min, q.r), r_max = std::max(r_max, q.r);
    z_min = std::min(z_min, q.z), z_max = std::max(z_max, q.z);
  }
  const double extent = std::max({r_max - r_min, z_max - z_min, std::abs(r_max)});
  const double tolerance = 1e-9 * extent;
  if (axisymmetric && r_min < -tolerance) {
    std::ostringstream msg;
    msg << g.source << ": axisymmetric geometry has a point at r = " << r_min
        << " m; expected r >= 0";
    throw InputError(msg.str());
  }
  const mesh::Point centre{axisymmetric ? 0.0 : 0.5 * (r_min + r_max), 0.5 * (z_min + z_max)};
  double bounding = 0.0;
  for (const mesh::Point& q : g.points) {
    bounding = std::max(bounding, std::hypot(q.r - centre.r, q.z - centre.z));
  }
  if (!(bounding > 0.0)) throw InputError(g.source + ": the geometry has zero extent");
  const double radius = p.outer_radius_factor * bounding;

  cases::BoundaryCondition outer;
  if (p.outer == cases::OuterBoundary::open) {
    outer = {"open (asymptotic dipole decay)", cases::BoundaryKind::mixed, 0.0, kNu0 / radius, 0.0};
  } else {
    outer = {"outer A = 0", cases::BoundaryKind::prescribed_a, 0.0, 0.0, 0.0};
  }
  p.boundaries.push_back(outer);
  p.outer = cases::OuterBoundary::none;  // the PSLG now contains its outer boundary
  const int marker = static_cast<int>(p.boundaries.size()) - 1;

  // Arc from angle -pi/2 to pi/2 (axisymmetric, measured from the r axis) or a full circle.
  const int chords = axisymmetric ? kOuterArcSegments : 2 * kOuterArcSegments;
  const double start = axisymmetric ? -0.5 * std::numbers::pi : 0.0;
  const double sweep = axisymmetric ? std::numbers::pi : 2.0 * std::numbers::pi;
  const int first = static_cast<int>(g.points.size());
  const int count = axisymmetric ? chords + 1 : chords;
  for (int k = 0; k < count; ++k) {
    const double angle = start + sweep * k / chords;
    double r = centre.r + radius * std::cos(angle);
    if (axisymmetric && (k == 0 || k == chords)) r = 0.0;
    g.points.push_back({r, centre.z + radius * std::sin(angle)});
  }
  for (int k = 0; k < chords; ++k) {
    g.segments.push_back({first + k, first + (k + 1) % count, marker, 0.0});
  }

  if (axisymmetric) {
    // Axis segments joining consecutive points on r = 0 (A = 0 is imposed there anyway).
    std::vector<std::pair<double, int>> on_axis;
    for (int i = 0; i < static_cast<int>(g.points.size()); ++i) {
      if (std::abs(g.points[i].r) <= tolerance) on_axis.push_back({g.points[i].z, i});
    }
    std::sort(on_axis.begin(), on_axis.end());
    std::set<std::pair<int, int>> existing;
    for (const mesh::Segment& s : g.segments) existing.insert(std::minmax(s.a, s.b));
    for (std::size_t k = 0; k + 1 < on_axis.size(); ++k) {
      const int a = on_axis[k].second, b = on_axis[k + 1].second;
      if (on_axis[k + 1].first - on_axis[k].first <= tolerance) continue;  // duplicate point
      if (!existing.count(std::minmax(a, b))) g.segments.push_back({a, b, -1, 0.0});
    }
  }

  if (g.default_region < 0) {
    mesh::RegionSeed air;
    air.seed = {centre.r + 0.5 * (bounding + radius), centre.z};
    air.name = "air";
    g.regions.push_back(air);
    g.default_region = static_cast<int>(g.regions.size()) - 1;
    cases::RegionData data;
    data.material = air_material(p);
    p.regions.resize(g.regions.size() - 1);
    p.regions.push_back(data);
  }
  return p;
}

}  // namespace rheomag::magnetostatics
