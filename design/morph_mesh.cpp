#include "design/morph_mesh.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/triangle.hpp"

namespace rheomag::design {

namespace {

constexpr double kMergeTolerance = 1e-9;  // [m]

std::vector<double> distinct_sorted(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  std::vector<double> out;
  for (double v : values)
    if (out.empty() || v - out.back() > kMergeTolerance) out.push_back(v);
  return out;
}

// Piecewise-linear map through knots (from[i] -> to[i]); `from` strictly increasing.
double map_coordinate(double x, const std::vector<double>& from, const std::vector<double>& to) {
  auto upper = std::upper_bound(from.begin(), from.end(), x);
  std::size_t i = upper == from.begin() ? 0 : static_cast<std::size_t>(upper - from.begin()) - 1;
  i = std::min(i, from.size() - 2);
  const double t = (x - from[i]) / (from[i + 1] - from[i]);
  return to[i] + t * (to[i + 1] - to[i]);
}

// Breakpoints extended by the mesh's own extent (fixed in both); false if `to` does not fit.
bool extended_knots(const std::vector<double>& from, const std::vector<double>& to, double low,
                    double high, std::vector<double>& from_knots, std::vector<double>& to_knots) {
  from_knots.clear();
  to_knots.clear();
  if (from.front() - low > kMergeTolerance) {
    if (!(to.front() - low > kMergeTolerance)) return false;
    from_knots.push_back(low);
    to_knots.push_back(low);
  }
  from_knots.insert(from_knots.end(), from.begin(), from.end());
  to_knots.insert(to_knots.end(), to.begin(), to.end());
  if (high - from.back() > kMergeTolerance) {
    if (!(high - to.back() > kMergeTolerance)) return false;
    from_knots.push_back(high);
    to_knots.push_back(high);
  }
  for (std::size_t i = 1; i < to_knots.size(); ++i)
    if (!(to_knots[i] > to_knots[i - 1])) return false;
  return from_knots.size() >= 2;
}

}  // namespace

Breakpoints geometry_breakpoints(const mesh::Pslg& pslg) {
  std::vector<double> r, z;
  for (const auto& p : pslg.points) {
    r.push_back(p.r);
    z.push_back(p.z);
  }
  return {distinct_sorted(std::move(r)), distinct_sorted(std::move(z))};
}

std::optional<mesh::Mesh> morph_mesh(const mesh::Mesh& mesh, const Breakpoints& from,
                                     const Breakpoints& to) {
  if (from.r.size() != to.r.size() || from.z.size() != to.z.size() || from.r.empty() ||
      from.z.empty() || mesh.vertex_count <= 0)
    return std::nullopt;
  double r_low = INFINITY, r_high = -INFINITY, z_low = INFINITY, z_high = -INFINITY;
  for (int i = 0; i < mesh.vertex_count; ++i) {
    r_low = std::min(r_low, mesh.nodes[i].r);
    r_high = std::max(r_high, mesh.nodes[i].r);
    z_low = std::min(z_low, mesh.nodes[i].z);
    z_high = std::max(z_high, mesh.nodes[i].z);
  }
  std::vector<double> r_from, r_to, z_from, z_to;
  if (!extended_knots(from.r, to.r, r_low, r_high, r_from, r_to) ||
      !extended_knots(from.z, to.z, z_low, z_high, z_from, z_to))
    return std::nullopt;
  mesh::Mesh out = mesh;
  for (int i = 0; i < mesh.vertex_count; ++i) {
    out.nodes[i].r = map_coordinate(mesh.nodes[i].r, r_from, r_to);
    out.nodes[i].z = map_coordinate(mesh.nodes[i].z, z_from, z_to);
  }
  for (const auto& t : out.triangles) {
    if (!(mesh::signed_triangle_area(out.nodes[t[0]], out.nodes[t[1]], out.nodes[t[2]]) > 0.0))
      return std::nullopt;
    if (out.order == 2) {
      for (int e = 0; e < 3; ++e) {
        const auto& a = out.nodes[t[e]];
        const auto& b = out.nodes[t[(e + 1) % 3]];
        out.nodes[t[3 + e]] = mesh::Point{0.5 * (a.r + b.r), 0.5 * (a.z + b.z)};
      }
    }
  }
  return out;
}

}  // namespace rheomag::design
