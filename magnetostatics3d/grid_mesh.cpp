#include "magnetostatics3d/grid_mesh.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace rheomag::magnetostatics3d {

std::vector<double> graded_axis(double start, const std::vector<AxisSpan>& spans) {
  std::vector<double> lines{start};
  for (const AxisSpan& s : spans) {
    const double length = s.end - lines.back();
    if (!(length > 0 && s.first_step > 0 && s.last_step > 0)) {
      throw InputError("grid axis: spans must increase and have positive steps");
    }
    const int n = std::max(
        1, static_cast<int>(std::ceil(length / (0.5 * (s.first_step + s.last_step)) - 1e-9)));
    const double ratio = n > 1 ? std::pow(s.last_step / s.first_step, 1.0 / (n - 1)) : 1.0;
    std::vector<double> step(n);
    double sum = 0.0;
    for (int k = 0; k < n; ++k) sum += step[k] = s.first_step * std::pow(ratio, k);
    const double origin = lines.back();
    double x = 0.0;
    for (int k = 0; k + 1 < n; ++k) lines.push_back(origin + (x += step[k] * length / sum));
    lines.push_back(s.end);
  }
  return lines;
}

TetMesh grid_mesh(const GridSpec& spec) {
  std::array<int, 3> n{};
  for (int d = 0; d < 3; ++d) {
    const auto& l = spec.lines[d];
    if (l.size() < 2 || !std::is_sorted(l.begin(), l.end()) ||
        std::adjacent_find(l.begin(), l.end()) != l.end()) {
      throw InputError("grid mesh: each axis needs at least two increasing grid lines");
    }
    n[d] = static_cast<int>(l.size());
  }
  TetMesh m;
  auto node = [&](int i, int j, int k) { return (k * n[1] + j) * n[0] + i; };
  m.nodes.reserve(static_cast<std::size_t>(n[0]) * n[1] * n[2]);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        m.nodes.emplace_back(spec.lines[0][i], spec.lines[1][j], spec.lines[2][k]);
  // Six tetrahedra per cell: the paths from corner (0,0,0) to (1,1,1) along the axes in each
  // of the six orders (the Kuhn split; every cell face is cut along the same diagonal).
  constexpr std::array<std::array<int, 3>, 6> kOrders{
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (int k = 0; k + 1 < n[2]; ++k)
    for (int j = 0; j + 1 < n[1]; ++j)
      for (int i = 0; i + 1 < n[0]; ++i) {
        const Eigen::Vector3d centre(0.5 * (spec.lines[0][i] + spec.lines[0][i + 1]),
                                     0.5 * (spec.lines[1][j] + spec.lines[1][j + 1]),
                                     0.5 * (spec.lines[2][k] + spec.lines[2][k + 1]));
        int region = spec.background_region;
        for (const RegionBox3d& b : spec.boxes)
          if (b.box.contains(centre)) region = b.region;
        for (const auto& order : kOrders) {
          std::array<int, 3> c{i, j, k};
          std::array<int, 4> tet{node(i, j, k), 0, 0, 0};
          for (int s = 0; s < 3; ++s) {
            ++c[order[s]];
            tet[s + 1] = node(c[0], c[1], c[2]);
          }
          m.tets.push_back(tet);
          if (m.volume(static_cast<int>(m.tets.size()) - 1) < 0) {
            std::swap(m.tets.back()[2], m.tets.back()[3]);
          }
          m.region.push_back(region);
        }
      }
  m.build_edges();
  // Boundary faces: tetrahedron faces used once, classified by the side they lie on.
  std::vector<std::array<int, 3>> faces;
  faces.reserve(4 * m.tets.size());
  for (const auto& t : m.tets)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f{};
      for (int a = 0, b = 0; a < 4; ++a)
        if (a != skip) f[b++] = t[a];
      std::sort(f.begin(), f.end());
      faces.push_back(f);
    }
  std::sort(faces.begin(), faces.end());
  for (std::size_t a = 0; a < faces.size();) {
    std::size_t b = a;
    while (b < faces.size() && faces[b] == faces[a]) ++b;
    if (b - a == 1) {
      for (int side = 0; side < 6; ++side) {
        const int d = side / 2;
        const double plane = side % 2 == 0 ? spec.lines[d].front() : spec.lines[d].back();
        const auto& f = faces[a];
        if (spec.sides[side] != FaceKind::interior && m.nodes[f[0]][d] == plane &&
            m.nodes[f[1]][d] == plane && m.nodes[f[2]][d] == plane) {
          m.faces.push_back(f);
          m.face_kind.push_back(spec.sides[side]);
          break;
        }
      }
    }
    a = b;
  }
  return m;
}

}  // namespace rheomag::magnetostatics3d
