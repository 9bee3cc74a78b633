#include "magnetostatics3d/coil_source.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include "magnetostatics/circuit_currents.hpp"
#include "mesh/triangle.hpp"

namespace rheomag::magnetostatics3d {
namespace {

/// One coil triangle of the meridian plane with its turn density [turns/m^2].
struct CoilTriangle {
  std::array<mesh::Point, 3> v;
  double density = 0.0;
};

/// The coil triangles of one circuit, their bounding box and the z of horizontal coil edges.
struct CircuitCoils {
  std::vector<CoilTriangle> triangles;
  double r_max = 0.0, z_min = 0.0, z_max = 0.0;
  std::vector<std::array<double, 2>> steps;  // (z, largest r) of horizontal boundary edges
  // Equal z slabs over z_min..z_max, each listing (in order) the triangles that reach into it.
  std::vector<std::vector<int>> slabs;
};

/// The slab of `coils` holding height z (z_min <= z <= z_max).
int slab_of(const CircuitCoils& coils, double z) {
  const int n = static_cast<int>(coils.slabs.size());
  const double h = (coils.z_max - coils.z_min) / n;
  const int k = h > 0.0 ? static_cast<int>(std::floor((z - coils.z_min) / h)) : 0;
  return std::clamp(k, 0, n - 1);
}

/// Lists each triangle in every slab its z range reaches, so a height's slab holds every
/// triangle that a horizontal line at that height can cross.
void fill_slabs(CircuitCoils& coils) {
  coils.slabs.assign(std::clamp<std::size_t>(coils.triangles.size() / 4, 1, 4096), {});
  for (int i = 0; i < static_cast<int>(coils.triangles.size()); ++i) {
    const auto& v = coils.triangles[i].v;
    const double lo = std::min({v[0].z, v[1].z, v[2].z});
    const double hi = std::max({v[0].z, v[1].z, v[2].z});
    for (int k = slab_of(coils, lo); k <= slab_of(coils, hi); ++k) coils.slabs[k].push_back(i);
  }
}

/// T_z(r, z) at unit current: sum of density x length of the triangle chord at z right of r.
double source_tz(const CircuitCoils& coils, double r, double z) {
  if (!(z >= coils.z_min && z <= coils.z_max) || r >= coils.r_max) return 0.0;
  double t = 0.0;
  for (const int i : coils.slabs[slab_of(coils, z)]) {
    const CoilTriangle& tri = coils.triangles[i];
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < 3; ++k) {
      const mesh::Point& p = tri.v[k];
      const mesh::Point& q = tri.v[(k + 1) % 3];
      if ((z - p.z) * (z - q.z) > 0.0 || p.z == q.z) continue;
      const double x = p.r + (z - p.z) / (q.z - p.z) * (q.r - p.r);
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    if (hi > lo) t += tri.density * std::max(0.0, hi - std::max(r, lo));
  }
  return t;
}

/// Integral of T_z over the tetrahedron with vertices x (degree-2 rule, `levels` bisections).
double integrate_tz(const SourceTz& tz, const std::array<Eigen::Vector3d, 4>& x, int levels) {
  if (levels > 0) {
    // Eight children by edge midpoints (four corners and the inner octahedron split in four).
    auto mid = [&](int i, int j) { return 0.5 * (x[i] + x[j]); };
    const Eigen::Vector3d m01 = mid(0, 1), m02 = mid(0, 2), m03 = mid(0, 3), m12 = mid(1, 2),
                          m13 = mid(1, 3), m23 = mid(2, 3);
    const std::array<std::array<Eigen::Vector3d, 4>, 8> children{{{x[0], m01, m02, m03},
                                                                  {m01, x[1], m12, m13},
                                                                  {m02, m12, x[2], m23},
                                                                  {m03, m13, m23, x[3]},
                                                                  {m01, m02, m03, m13},
                                                                  {m01, m02, m12, m13},
                                                                  {m02, m03, m13, m23},
                                                                  {m02, m12, m13, m23}}};
    double sum = 0.0;
    for (const auto& c : children) sum += integrate_tz(tz, c, levels - 1);
    return sum;
  }
  const double volume = std::abs((x[1] - x[0]).dot((x[2] - x[0]).cross(x[3] - x[0]))) / 6.0;
  constexpr double a = 0.5854101966249685, b = 0.1381966011250105;  // degree-2 4-point rule
  double sum = 0.0;
  for (int q = 0; q < 4; ++q) {
    sum += tz(b * (x[0] + x[1] + x[2] + x[3]) + (a - b) * x[q]);
  }
  return 0.25 * volume * sum;
}

std::vector<CircuitCoils> collect_coils(const cases::Problem& closed, const mesh::Mesh& meridian) {
  std::vector<CircuitCoils> coils(closed.circuits.size());
  std::vector<double> area(closed.regions.size(), 0.0);
  auto vertices = [&](std::size_t e) {
    const auto& t = meridian.triangles[e];
    return std::array<mesh::Point, 3>{meridian.nodes[t[0]], meridian.nodes[t[1]],
                                      meridian.nodes[t[2]]};
  };
  for (std::size_t e = 0; e < meridian.triangles.size(); ++e) {
    const auto v = vertices(e);
    area[meridian.region[e]] += mesh::triangle_area(v[0], v[1], v[2]);
  }
  // The current density per ampere of each coil region (a winding's turns / area).
  const std::vector<magnetostatics::RegionCurrent> shares =
      magnetostatics::circuit_currents(closed, meridian, area);
  // Edge use count per region: an edge used once is on the region's boundary.
  std::map<std::array<int, 3>, int> uses;
  for (std::size_t e = 0; e < meridian.triangles.size(); ++e) {
    const cases::RegionData& rd = closed.regions[meridian.region[e]];
    const magnetostatics::RegionCurrent& share = shares[meridian.region[e]];
    if (rd.circuit < 0 || share.per_amp == 0.0) continue;
    CircuitCoils& c = coils[rd.circuit];
    const auto v = vertices(e);
    if (c.triangles.empty()) {
      c.r_max = -INFINITY;
      c.z_min = INFINITY;
      c.z_max = -INFINITY;
    }
    c.triangles.push_back(
        {v, share.per_amp * share.g(mesh::triangle_centroid(v[0], v[1], v[2]).r)});
    for (int k = 0; k < 3; ++k) {
      c.r_max = std::max(c.r_max, v[k].r);
      c.z_min = std::min(c.z_min, v[k].z);
      c.z_max = std::max(c.z_max, v[k].z);
      int a = meridian.triangles[e][k], b = meridian.triangles[e][(k + 1) % 3];
      ++uses[{meridian.region[e], std::min(a, b), std::max(a, b)}];
    }
  }
  for (const auto& [key, count] : uses) {
    const mesh::Point& p = meridian.nodes[key[1]];
    const mesh::Point& q = meridian.nodes[key[2]];
    if (count == 1 && p.z == q.z) {
      coils[closed.regions[key[0]].circuit].steps.push_back({p.z, std::max(p.r, q.r)});
    }
  }
  for (CircuitCoils& c : coils)
    if (!c.triangles.empty()) fill_slabs(c);
  return coils;
}

}  // namespace

std::vector<std::function<double(double, double)>> circuit_source_tz(const cases::Problem& closed,
                                                                     const mesh::Mesh& meridian) {
  const auto coils =
      std::make_shared<const std::vector<CircuitCoils>>(collect_coils(closed, meridian));
  std::vector<std::function<double(double, double)>> tz;
  for (std::size_t c = 0; c < coils->size(); ++c) {
    tz.emplace_back([coils, c](double r, double z) {
      const CircuitCoils& coil = (*coils)[c];
      return coil.triangles.empty() ? 0.0 : source_tz(coil, r, z);
    });
  }
  return tz;
}

Eigen::VectorXd z_source_loads(const TetMesh& mesh, const std::vector<Eigen::Vector3d>& nodes,
                               const SourceTz& tz, double z_min, double z_max,
                               const std::function<bool(double, double)>& jumps) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh.edges.size()));
  for (int t = 0; t < static_cast<int>(mesh.tets.size()); ++t) {
    std::array<Eigen::Vector3d, 4> x;
    double z_lo = INFINITY, z_hi = -INFINITY;
    for (int k = 0; k < 4; ++k) {
      x[k] = nodes[mesh.tets[t][k]];
      z_lo = std::min(z_lo, x[k][2]);
      z_hi = std::max(z_hi, x[k][2]);
    }
    if (z_hi < z_min || z_lo > z_max) continue;
    const double integral = integrate_tz(tz, x, jumps(z_lo, z_hi) ? 2 : 0);
    if (integral == 0.0) continue;
    const auto curls = edge_curls(mesh, t);
    for (int e = 0; e < 6; ++e) f[mesh.tet_edges[t][e]] += curls[e][2] * integral;
  }
  return f;
}

std::vector<Eigen::VectorXd> circuit_loads(const cases::Problem& closed, const mesh::Mesh& meridian,
                                           const TetMesh& mesh,
                                           const std::vector<Eigen::Vector3d>& source_nodes) {
  const std::vector<CircuitCoils> coils = collect_coils(closed, meridian);
  std::vector<Eigen::VectorXd> loads;
  for (const CircuitCoils& c : coils) {
    if (c.triangles.empty()) {
      loads.push_back(Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh.edges.size())));
      continue;
    }
    const auto jumps = [&](double z_lo, double z_hi) {
      return std::any_of(c.steps.begin(), c.steps.end(),
                         [&](const auto& s) { return s[0] > z_lo && s[0] < z_hi; });
    };
    const auto tz = [&](const Eigen::Vector3d& p) {
      return source_tz(c, std::hypot(p[0], p[1]), p[2]);
    };
    loads.push_back(z_source_loads(mesh, source_nodes, tz, c.z_min, c.z_max, jumps));
  }
  return loads;
}

}  // namespace rheomag::magnetostatics3d
