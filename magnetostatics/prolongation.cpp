#include "magnetostatics/prolongation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "magnetostatics/lagrange.hpp"

namespace rheomag::magnetostatics {
namespace {

/// Triangles of a mesh sorted into the cells of a uniform grid over its bounding box (each
/// triangle in every cell its bounding box overlaps), in compressed rows.
class TriangleGrid {
 public:
  explicit TriangleGrid(const mesh::Mesh& m) : mesh_(m) {
    double r1 = -std::numeric_limits<double>::infinity(), z1 = r1;
    r0_ = z0_ = std::numeric_limits<double>::infinity();
    for (const mesh::Point& p : m.nodes) {
      r0_ = std::min(r0_, p.r), r1 = std::max(r1, p.r);
      z0_ = std::min(z0_, p.z), z1 = std::max(z1, p.z);
    }
    // About one triangle per cell, cells as square as the box allows.
    const double width = std::max(r1 - r0_, 1e-300), height = std::max(z1 - z0_, 1e-300);
    const double cells = std::max<double>(1.0, static_cast<double>(m.triangles.size()));
    const double side = std::sqrt(width * height / cells);
    nr_ = std::clamp(static_cast<int>(width / side), 1, 1 << 14);
    nz_ = std::clamp(static_cast<int>(height / side), 1, 1 << 14);
    hr_ = width / nr_, hz_ = height / nz_;
    start_.assign(static_cast<std::size_t>(nr_) * nz_ + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<int> fill(start_.begin(), start_.end() - 1);
      if (pass == 1) items_.resize(start_.back());
      for (int e = 0; e < static_cast<int>(m.triangles.size()); ++e) {
        const auto [i0, i1, j0, j1] = box(e);
        for (int j = j0; j <= j1; ++j) {
          for (int i = i0; i <= i1; ++i) {
            const std::size_t c = cell(i, j);
            if (pass == 0) {
              ++start_[c + 1];
            } else {
              items_[fill[c]++] = e;
            }
          }
        }
      }
      if (pass == 0) {
        for (std::size_t c = 0; c + 1 < start_.size(); ++c) start_[c + 1] += start_[c];
      }
    }
  }

  /// Triangle and reference coordinates of p: the containing triangle, or else the triangle of
  /// the nearest non-empty cells that p is least outside of, with p moved onto it.
  void locate(mesh::Point p, int& element, double& xi, double& eta) const {
    const int ci = column(p.r), cj = row(p.z);
    double best = std::numeric_limits<double>::infinity();
    for (int ring = 0; ring <= std::max(nr_, nz_); ++ring) {
      for (int j = cj - ring; j <= cj + ring; ++j) {
        for (int i = ci - ring; i <= ci + ring; ++i) {
          if (i < 0 || j < 0 || i >= nr_ || j >= nz_) continue;
          if (std::max(std::abs(i - ci), std::abs(j - cj)) != ring) continue;
          for (int k = start_[cell(i, j)]; k < start_[cell(i, j) + 1]; ++k) {
            double x, y;
            const double outside = reference(items_[k], p, x, y);
            if (outside < best) best = outside, element = items_[k], xi = x, eta = y;
            if (outside <= 1e-12) return;
          }
        }
      }
      if (std::isfinite(best)) break;  // the closest ring holding triangles
    }
    // Outside every triangle: clip the barycentric coordinates onto the triangle.
    xi = std::max(xi, 0.0), eta = std::max(eta, 0.0);
    if (xi + eta > 1.0) {
      const double sum = xi + eta;
      xi /= sum, eta /= sum;
    }
  }

 private:
  int column(double r) const { return std::clamp(static_cast<int>((r - r0_) / hr_), 0, nr_ - 1); }
  int row(double z) const { return std::clamp(static_cast<int>((z - z0_) / hz_), 0, nz_ - 1); }
  std::size_t cell(int i, int j) const { return static_cast<std::size_t>(j) * nr_ + i; }
  std::array<int, 4> box(int e) const {
    const auto& t = mesh_.triangles[e];
    double ra = mesh_.nodes[t[0]].r, rb = ra, za = mesh_.nodes[t[0]].z, zb = za;
    for (int v = 1; v < 3; ++v) {
      ra = std::min(ra, mesh_.nodes[t[v]].r), rb = std::max(rb, mesh_.nodes[t[v]].r);
      za = std::min(za, mesh_.nodes[t[v]].z), zb = std::max(zb, mesh_.nodes[t[v]].z);
    }
    return {column(ra), column(rb), row(za), row(zb)};
  }
  /// Reference coordinates of p in triangle e; returns how far outside it lies (largest negative
  /// barycentric coordinate, 0 inside).
  double reference(int e, mesh::Point p, double& xi, double& eta) const {
    const auto& t = mesh_.triangles[e];
    const mesh::Point a = mesh_.nodes[t[0]], b = mesh_.nodes[t[1]], c = mesh_.nodes[t[2]];
    const double r10 = b.r - a.r, r20 = c.r - a.r, z10 = b.z - a.z, z20 = c.z - a.z;
    const double det = r10 * z20 - r20 * z10;
    const double dr = p.r - a.r, dz = p.z - a.z;
    xi = (z20 * dr - r20 * dz) / det;
    eta = (-z10 * dr + r10 * dz) / det;
    return std::max({0.0, -xi, -eta, xi + eta - 1.0});
  }

  const mesh::Mesh& mesh_;
  double r0_, z0_, hr_ = 1.0, hz_ = 1.0;
  int nr_ = 1, nz_ = 1;
  std::vector<int> start_, items_;
};

}  // namespace

Eigen::VectorXd interpolate_nodal(const mesh::Mesh& from, const Eigen::VectorXd& values,
                                  const mesh::Mesh& to) {
  const TriangleGrid grid(from);
  const int k = from.nodes_per_triangle();
  Eigen::VectorXd out(static_cast<Eigen::Index>(to.nodes.size()));
  double n[kMaxElementNodes], d_xi[kMaxElementNodes], d_eta[kMaxElementNodes];
  for (std::size_t node = 0; node < to.nodes.size(); ++node) {
    int e = 0;
    double xi = 0.0, eta = 0.0;
    grid.locate(to.nodes[node], e, xi, eta);
    lagrange_basis(from.order, xi, eta, n, d_xi, d_eta);
    double v = 0.0;
    for (int i = 0; i < k; ++i) v += n[i] * values[from.triangles[e][i]];
    out[static_cast<Eigen::Index>(node)] = v;
  }
  return out;
}

}  // namespace rheomag::magnetostatics
