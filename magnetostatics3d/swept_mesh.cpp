#include "magnetostatics3d/swept_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace rheomag::magnetostatics3d {

Revolution graded_revolution(double span, const std::vector<double>& walls, double fine,
                             double coarse, double growth) {
  if (!(fine > 0) || !(coarse >= fine) || !(growth >= 1.0))
    throw InputError("3D swept mesh: angular steps must satisfy 0 < fine <= coarse, growth >= 1");
  // Step size at angle phi: fine at a wall, growing linearly with the distance (a geometric
  // progression of steps), capped at coarse.
  auto step = [&](double phi) {
    double d = INFINITY;
    for (double w : walls) d = std::min(d, std::abs(phi - w));
    return std::isfinite(d) ? std::min(coarse, fine + (growth - 1.0) * d) : coarse;
  };
  std::vector<double> breaks = walls;
  breaks.push_back(0.0);
  breaks.push_back(span);
  std::sort(breaks.begin(), breaks.end());
  Revolution rev;
  rev.full = std::abs(span - 2.0 * 3.14159265358979323846) < 1e-9;
  rev.angles.push_back(breaks.front());
  for (std::size_t i = 1; i < breaks.size(); ++i) {
    const double a = breaks[i - 1], b = breaks[i];
    if (b - a < 1e-9) continue;
    // March with the local step, then scale the steps to end exactly on b.
    std::vector<double> steps;
    for (double phi = a; phi < b - 1e-12;) {
      const double h = std::min(step(phi), step(std::min(b, phi + step(phi))));
      steps.push_back(h);
      phi += h;
    }
    double total = 0.0;
    for (double h : steps) total += h;
    if (steps.size() > 1 && total - steps.back() > b - a - 0.5 * steps.back()) {
      total -= steps.back();  // the last step overshoots by more than half: drop it
      steps.pop_back();
    }
    double phi = a;
    for (std::size_t k = 0; k + 1 < steps.size(); ++k) {
      phi += steps[k] * (b - a) / total;
      rev.angles.push_back(phi);
    }
    rev.angles.push_back(b);
  }
  return rev;
}

TetMesh sweep_mesh(const mesh::Mesh& meridian, const Revolution& rev) {
  if (meridian.order != 1) throw InputError("3D swept mesh: the meridian mesh must be linear");
  const int intervals = static_cast<int>(rev.angles.size()) - 1;
  const int columns = rev.full ? intervals : intervals + 1;
  double scale = 0.0;
  for (const mesh::Point& p : meridian.nodes) scale = std::max(scale, std::hypot(p.r, p.z));
  const double axis_tol = 1e-12 * scale;

  TetMesh m;
  const std::size_t n2 = meridian.nodes.size();
  std::vector<int> first(n2);
  std::vector<bool> on_axis(n2);
  std::vector<int> column_of;  // per 3D node, -1 on the axis
  std::vector<int> meridian_of;
  for (std::size_t i = 0; i < n2; ++i) {
    const mesh::Point& p = meridian.nodes[i];
    on_axis[i] = p.r <= axis_tol;
    first[i] = static_cast<int>(m.nodes.size());
    for (int k = 0; k < (on_axis[i] ? 1 : columns); ++k) {
      const double r = on_axis[i] ? 0.0 : p.r;
      m.nodes.emplace_back(r * std::cos(rev.angles[k]), r * std::sin(rev.angles[k]), p.z);
      column_of.push_back(on_axis[i] ? -1 : k);
      meridian_of.push_back(static_cast<int>(i));
    }
  }
  auto node = [&](int i, int k) {
    if (on_axis[i]) return first[i];
    return first[i] + (k == intervals && rev.full ? 0 : k);
  };

  for (std::size_t e = 0; e < meridian.triangles.size(); ++e) {
    std::array<int, 3> v{meridian.triangles[e][0], meridian.triangles[e][1],
                         meridian.triangles[e][2]};
    std::sort(v.begin(), v.end());
    for (int k = 0; k < intervals; ++k) {
      const int a = node(v[0], k), b = node(v[1], k), c = node(v[2], k);
      const int a1 = node(v[0], k + 1), b1 = node(v[1], k + 1), c1 = node(v[2], k + 1);
      const std::array<std::array<int, 4>, 3> split{
          {{a, b, c, c1}, {a, b, b1, c1}, {a, a1, b1, c1}}};
      for (const auto& t : split) {
        std::array<int, 4> s = t;
        std::sort(s.begin(), s.end());
        if (std::adjacent_find(s.begin(), s.end()) != s.end()) continue;  // collapsed at the axis
        m.tets.push_back(t);
        m.region.push_back(meridian.region[e]);
        if (m.volume(static_cast<int>(m.tets.size()) - 1) < 0)
          std::swap(m.tets.back()[2], m.tets.back()[3]);
      }
    }
  }

  // Faces of exactly one tetrahedron: outer (swept from a marked edge) or symmetry (end plane).
  std::set<std::pair<int, int>> marked;
  for (const mesh::BoundaryEdge& b : meridian.boundary_edges) {
    if (b.boundary >= 0)
      marked.insert({std::min(b.nodes[0], b.nodes[1]), std::max(b.nodes[0], b.nodes[1])});
  }
  std::vector<std::array<int, 4>> faces;  // sorted nodes, tet
  faces.reserve(4 * m.tets.size());
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 4> f{};
      int n = 0;
      for (int k = 0; k < 4; ++k)
        if (k != skip) f[n++] = m.tets[t][k];
      std::sort(f.begin(), f.begin() + 3);
      f[3] = static_cast<int>(t);
      faces.push_back(f);
    }
  }
  std::sort(faces.begin(), faces.end());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const bool shared_before =
        i > 0 && std::equal(faces[i].begin(), faces[i].begin() + 3, faces[i - 1].begin());
    const bool shared_after =
        i + 1 < faces.size() &&
        std::equal(faces[i].begin(), faces[i].begin() + 3, faces[i + 1].begin());
    if (shared_before || shared_after) continue;
    const std::array<int, 3> f{faces[i][0], faces[i][1], faces[i][2]};
    if (!rev.full) {
      for (int end : {0, intervals}) {
        if (std::all_of(f.begin(), f.end(),
                        [&](int p) { return column_of[p] == end || column_of[p] < 0; })) {
          m.faces.push_back(f);
          m.face_kind.push_back(FaceKind::symmetry);
          break;
        }
      }
      if (!m.faces.empty() && m.faces.back() == f) continue;
    }
    std::set<int> ids{meridian_of[f[0]], meridian_of[f[1]], meridian_of[f[2]]};
    if (ids.size() == 2 && marked.count({*ids.begin(), *ids.rbegin()})) {
      m.faces.push_back(f);
      m.face_kind.push_back(FaceKind::outer);
    }
  }
  m.build_edges();
  return m;
}

std::vector<double> ring_area_factors(const Revolution& rev) {
  const int intervals = static_cast<int>(rev.angles.size()) - 1;
  std::vector<double> q(intervals);
  for (int k = 0; k < intervals; ++k) {
    const double d = rev.angles[k + 1] - rev.angles[k];
    q[k] = d / std::sin(d);
  }
  std::vector<double> c(rev.angles.size(), 1.0);
  for (int k = 0; k <= intervals; ++k) {
    int before = k - 1, after = k;
    if (rev.full) {
      before = (k - 1 + intervals) % intervals;
      after = k % intervals;
    } else if (k == 0) {
      before = 0;
    } else if (k == intervals) {
      after = intervals - 1;
    }
    c[k] = std::pow(q[before] * q[after], 0.25);
  }
  return c;
}

void restore_ring_areas(std::vector<Eigen::Vector3d>& nodes,
                        const std::vector<Eigen::Vector3d>& swept, const Revolution& rev) {
  const std::vector<double> c = ring_area_factors(rev);
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    if (swept[n][0] == 0.0 && swept[n][1] == 0.0) continue;  // on the axis
    double phi = std::atan2(swept[n][1], swept[n][0]);
    if (phi < -1e-12) phi += kTwoPi;
    const auto it = std::lower_bound(rev.angles.begin(), rev.angles.end(), phi);
    std::size_t k = static_cast<std::size_t>(it - rev.angles.begin());
    if (k == rev.angles.size() || (k > 0 && phi - rev.angles[k - 1] < rev.angles[k] - phi)) --k;
    nodes[n][0] *= c[k];
    nodes[n][1] *= c[k];
  }
}

}  // namespace rheomag::magnetostatics3d
