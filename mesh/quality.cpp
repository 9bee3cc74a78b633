// Quality statistics of a mesh (see quality.hpp).

#include "mesh/quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <unordered_map>

#include "mesh/edge_key.hpp"
#include "mesh/triangle.hpp"

namespace rheomag::mesh {

namespace {

double length(const Point& a, const Point& b) {
  return std::hypot(b.r - a.r, b.z - a.z);
}

/// Angle at `at` between the edges towards p and q [deg].
double angle(const Point& at, const Point& p, const Point& q) {
  const double ur = p.r - at.r, uz = p.z - at.z, vr = q.r - at.r, vz = q.z - at.z;
  return std::atan2(std::abs(ur * vz - uz * vr), ur * vr + uz * vz) * 180.0 / std::numbers::pi;
}

const char* gap_name(GapKind gap) {
  switch (gap) {
    case GapKind::annular:
      return "annular gap";
    case GapKind::radial:
      return "radial gap";
    case GapKind::none:
      break;
  }
  return "";
}

}  // namespace

double band_thickness(double area, double perimeter) {
  const double half_perimeter = 0.5 * perimeter;
  const double discriminant = std::max(0.0, half_perimeter * half_perimeter - 4.0 * area);
  // The smaller root in the cancellation-free form 2A / (P/2 + sqrt(discriminant)).
  const double denominator = half_perimeter + std::sqrt(discriminant);
  return denominator > 0.0 ? 2.0 * area / denominator : 0.0;
}

MeshQuality measure_quality(const Mesh& mesh, const Pslg& pslg) {
  MeshQuality q;
  q.elements = static_cast<int>(mesh.triangles.size());
  q.nodes = static_cast<int>(mesh.nodes.size());
  q.order = mesh.order;
  q.min_angle = mesh.triangles.empty() ? 0.0 : 180.0;
  q.regions.resize(pslg.regions.size());
  for (std::size_t r = 0; r < pslg.regions.size(); ++r) {
    q.regions[r].name = pslg.regions[r].name;
    q.regions[r].gap = pslg.regions[r].gap;
  }
  std::vector<double> perimeter(pslg.regions.size(), 0.0);
  // Region of the triangles on each side of an edge: an edge seen once, or seen from two
  // regions, lies on its region's boundary.
  std::unordered_map<std::uint64_t, std::pair<int, int>> edge_regions;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Point& a = mesh.nodes[static_cast<std::size_t>(tri[0])];
    const Point& b = mesh.nodes[static_cast<std::size_t>(tri[1])];
    const Point& c = mesh.nodes[static_cast<std::size_t>(tri[2])];
    const double ab = length(a, b), bc = length(b, c), ca = length(c, a);
    const double longest = std::max({ab, bc, ca});
    const double area = triangle_area(a, b, c);
    q.min_angle = std::min({q.min_angle, angle(a, b, c), angle(b, c, a), angle(c, a, b)});
    q.max_aspect_ratio =
        std::max(q.max_aspect_ratio, longest * (ab + bc + ca) / (4.0 * std::sqrt(3.0) * area));
    const int region = mesh.region[t];
    if (region < 0 || region >= static_cast<int>(q.regions.size())) continue;
    RegionQuality& rq = q.regions[static_cast<std::size_t>(region)];
    ++rq.elements;
    rq.area += area;
    rq.max_edge = std::max(rq.max_edge, longest);
    for (int i = 0; i < 3; ++i) {
      auto [it, inserted] =
          edge_regions.try_emplace(edge_key(tri[i], tri[(i + 1) % 3]), std::pair(region, -1));
      if (!inserted) it->second.second = region;
    }
  }
  for (const auto& [key, regions] : edge_regions) {
    if (regions.first == regions.second) continue;
    const Point& a = mesh.nodes[key >> 32];
    const Point& b = mesh.nodes[key & 0xffffffffu];
    perimeter[static_cast<std::size_t>(regions.first)] += length(a, b);
    if (regions.second >= 0) perimeter[static_cast<std::size_t>(regions.second)] += length(a, b);
  }
  for (std::size_t r = 0; r < q.regions.size(); ++r) {
    RegionQuality& rq = q.regions[r];
    rq.thickness = band_thickness(rq.area, perimeter[r]);
    rq.elements_across = rq.max_edge > 0.0 ? rq.thickness / rq.max_edge : 0.0;
  }
  return q;
}

nlohmann::json quality_json(const MeshQuality& q) {
  nlohmann::json regions = nlohmann::json::array();
  for (const RegionQuality& r : q.regions) {
    nlohmann::json row = {
        {"name", r.name}, {"elements", r.elements}, {"area", r.area}, {"max_edge", r.max_edge}};
    if (r.gap != GapKind::none) {
      row["thickness"] = r.thickness;
      row["elements_across"] = r.elements_across;
    }
    regions.push_back(row);
  }
  return {{"elements", q.elements},
          {"nodes", q.nodes},
          {"order", q.order},
          {"min_angle_deg", q.min_angle},
          {"max_aspect_ratio", q.max_aspect_ratio},
          {"regions", regions}};
}

std::string format_quality(const MeshQuality& q) {
  char line[256];
  std::snprintf(line, sizeof line,
                "mesh: %d elements (P%d), %d nodes, min angle %.2f deg, max aspect ratio %.2f\n",
                q.elements, q.order, q.nodes, q.min_angle, q.max_aspect_ratio);
  std::string out = line;
  std::snprintf(line, sizeof line, "  %-16s %9s %12s %12s %12s  %s\n", "region", "elements",
                "area [m^2]", "max edge [m]", "thickness[m]", "elements across");
  out += line;
  for (const RegionQuality& r : q.regions) {
    std::snprintf(line, sizeof line, "  %-16s %9d %12.4g %12.4g %12.4g  ", r.name.c_str(),
                  r.elements, r.area, r.max_edge, r.thickness);
    out += line;
    if (r.gap != GapKind::none) {
      std::snprintf(line, sizeof line, "%.1f (%s)", r.elements_across, gap_name(r.gap));
      out += line;
    }
    out += "\n";
  }
  return out;
}

}  // namespace rheomag::mesh
