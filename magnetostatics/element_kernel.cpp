#include "magnetostatics/element_kernel.hpp"

#include <cmath>
#include <numbers>

namespace rheomag::magnetostatics {

void b_operator(Symmetry symmetry, int order, const std::array<mesh::Point, 3>& v, double xi,
                double eta, double* n, double* g_r, double* g_z) {
  double d_xi[kMaxElementNodes], d_eta[kMaxElementNodes];
  lagrange_basis(order, xi, eta, n, d_xi, d_eta);
  const double r10 = v[1].r - v[0].r, r20 = v[2].r - v[0].r;
  const double z10 = v[1].z - v[0].z, z20 = v[2].z - v[0].z;
  const double inv_det = 1.0 / (r10 * z20 - r20 * z10);  // one division per point, not 2 per node
  const int nodes = order == 1 ? 3 : 6;
  const double r = v[0].r + xi * r10 + eta * r20;
  const double inv_r = r > 0.0 ? 1.0 / r : 0.0;
  for (int i = 0; i < nodes; ++i) {
    const double dn_dr = (z20 * d_xi[i] - z10 * d_eta[i]) * inv_det;
    const double dn_dz = (-r20 * d_xi[i] + r10 * d_eta[i]) * inv_det;
    if (symmetry == Symmetry::axisymmetric) {
      g_r[i] = -dn_dz;
      // B_z = dA/dr + A/r; on the axis (A = 0 there) A/r -> dA/dr.
      g_z[i] = r > 0.0 ? dn_dr + n[i] * inv_r : 2.0 * dn_dr;
    } else {
      g_r[i] = dn_dz;
      g_z[i] = -dn_dr;
    }
  }
}

void element_quadrature(Symmetry symmetry, double depth, int order,
                        const std::array<mesh::Point, 3>& v, ElementQuadrature& q) {
  const auto& rule = triangle_quadrature(order);
  q.nodes = order == 1 ? 3 : 6;
  q.points = static_cast<int>(rule.size());
  const double area =
      0.5 * std::abs((v[1].r - v[0].r) * (v[2].z - v[0].z) - (v[2].r - v[0].r) * (v[1].z - v[0].z));
  for (int p = 0; p < q.points; ++p) {
    const double xi = rule[p].xi, eta = rule[p].eta;
    b_operator(symmetry, order, v, xi, eta, q.n[p].data(), q.g_r[p].data(), q.g_z[p].data());
    q.r[p] = v[0].r + xi * (v[1].r - v[0].r) + eta * (v[2].r - v[0].r);
    q.z[p] = v[0].z + xi * (v[1].z - v[0].z) + eta * (v[2].z - v[0].z);
    q.area_weight[p] = area * rule[p].weight;
    q.weight[p] = q.area_weight[p] *
                  (symmetry == Symmetry::axisymmetric ? 2.0 * std::numbers::pi * q.r[p] : depth);
  }
}

std::array<double, 2> element_b(const ElementQuadrature& q, int p, const double* a) {
  double br = 0.0, bz = 0.0;
  for (int i = 0; i < q.nodes; ++i) {
    br += a[i] * q.g_r[p][i];
    bz += a[i] * q.g_z[p][i];
  }
  return {br, bz};
}

void element_residual_tangent(const ElementQuadrature& q, const double* a, const Reluctivity& law,
                              double* residual, double* tangent) {
  const int m = q.nodes;
  for (int i = 0; i < m; ++i) residual[i] = 0.0;
  if (tangent) {
    for (int i = 0; i < m * m; ++i) tangent[i] = 0.0;
  }
  for (int p = 0; p < q.points; ++p) {
    const auto [br, bz] = element_b(q, p, a);
    const double b2 = br * br + bz * bz;
    const double nu = law.nu(b2), w = q.weight[p];
    double b_dot_g[kMaxElementNodes];
    for (int i = 0; i < m; ++i) {
      b_dot_g[i] = br * q.g_r[p][i] + bz * q.g_z[p][i];
      residual[i] += w * nu * b_dot_g[i];
    }
    if (!tangent) continue;
    const double rank_one = 2.0 * law.dnu_db2(b2);
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j <= i; ++j) {  // lower triangle; mirrored below (K is symmetric)
        tangent[i * m + j] += w * (nu * (q.g_r[p][i] * q.g_r[p][j] + q.g_z[p][i] * q.g_z[p][j]) +
                                   rank_one * b_dot_g[i] * b_dot_g[j]);
      }
    }
  }
  if (tangent) {
    for (int i = 0; i < m; ++i) {
      for (int j = i + 1; j < m; ++j) tangent[i * m + j] = tangent[j * m + i];
    }
  }
}

void element_source(const ElementQuadrature& q, double* source) {
  for (int i = 0; i < q.nodes; ++i) source[i] = 0.0;
  for (int p = 0; p < q.points; ++p) {
    for (int i = 0; i < q.nodes; ++i) source[i] += q.weight[p] * q.n[p][i];
  }
}

std::array<double, 2> element_energy(const ElementQuadrature& q, const double* a,
                                     const Reluctivity& law) {
  double energy = 0.0, b_dot_h = 0.0;
  for (int p = 0; p < q.points; ++p) {
    const auto [br, bz] = element_b(q, p, a);
    const double b2 = br * br + bz * bz;
    energy += q.weight[p] * law.energy_density(b2);
    b_dot_h += q.weight[p] * law.nu(b2) * b2;
  }
  return {energy, b_dot_h};
}

}  // namespace rheomag::magnetostatics
