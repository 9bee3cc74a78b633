#include "magnetostatics/element_kernel.hpp"

#include <cmath>
#include <numbers>

#include "mesh/triangle.hpp"

namespace rheomag::magnetostatics {

void b_operator(cases::Symmetry symmetry, int order, const std::array<mesh::Point, 3>& v, double xi,
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
    if (symmetry == cases::Symmetry::axisymmetric) {
      g_r[i] = -dn_dz;
      // B_z = dA/dr + A/r; on the axis (A = 0 there) A/r -> dA/dr.
      g_z[i] = r > 0.0 ? dn_dr + n[i] * inv_r : 2.0 * dn_dr;
    } else {
      g_r[i] = dn_dz;
      g_z[i] = -dn_dr;
    }
  }
}

namespace {

/// Shape functions and their reference derivatives at the quadrature points of one order,
/// evaluated once (the same for every triangle).
struct ReferenceElement {
  int nodes = 0, points = 0;
  double xi[kMaxQuadraturePoints], eta[kMaxQuadraturePoints], weight[kMaxQuadraturePoints];
  double n[kMaxQuadraturePoints][kMaxElementNodes];
  double d_xi[kMaxQuadraturePoints][kMaxElementNodes];
  double d_eta[kMaxQuadraturePoints][kMaxElementNodes];
};

ReferenceElement make_reference(int order) {
  ReferenceElement ref;
  const auto& rule = triangle_quadrature(order);
  ref.nodes = order == 1 ? 3 : 6;
  ref.points = static_cast<int>(rule.size());
  for (int p = 0; p < ref.points; ++p) {
    ref.xi[p] = rule[p].xi, ref.eta[p] = rule[p].eta, ref.weight[p] = rule[p].weight;
    lagrange_basis(order, rule[p].xi, rule[p].eta, ref.n[p], ref.d_xi[p], ref.d_eta[p]);
  }
  return ref;
}

const ReferenceElement& reference_element(int order) {
  static const ReferenceElement p1 = make_reference(1), p2 = make_reference(2);
  return order == 1 ? p1 : p2;
}

}  // namespace

void element_quadrature(cases::Symmetry symmetry, double depth, int order,
                        const std::array<mesh::Point, 3>& v, ElementQuadrature& q) {
  // Same arithmetic as b_operator, with the reference shape functions tabulated once.
  const ReferenceElement& ref = reference_element(order);
  q.nodes = ref.nodes;
  q.points = ref.points;
  const double r10 = v[1].r - v[0].r, r20 = v[2].r - v[0].r;
  const double z10 = v[1].z - v[0].z, z20 = v[2].z - v[0].z;
  const double inv_det = 1.0 / (r10 * z20 - r20 * z10);
  const double area = mesh::triangle_area(v[0], v[1], v[2]);
  const bool axisymmetric = symmetry == cases::Symmetry::axisymmetric;
  for (int p = 0; p < ref.points; ++p) {
    const double xi = ref.xi[p], eta = ref.eta[p];
    const double r = v[0].r + xi * r10 + eta * r20;
    const double inv_r = r > 0.0 ? 1.0 / r : 0.0;
    double* n = q.n[p].data();
    double* g_r = q.g_r[p].data();
    double* g_z = q.g_z[p].data();
    for (int i = 0; i < ref.nodes; ++i) {
      n[i] = ref.n[p][i];
      const double dn_dr = (z20 * ref.d_xi[p][i] - z10 * ref.d_eta[p][i]) * inv_det;
      const double dn_dz = (-r20 * ref.d_xi[p][i] + r10 * ref.d_eta[p][i]) * inv_det;
      if (axisymmetric) {
        g_r[i] = -dn_dz;
        g_z[i] = r > 0.0 ? dn_dr + n[i] * inv_r : 2.0 * dn_dr;
      } else {
        g_r[i] = dn_dz;
        g_z[i] = -dn_dr;
      }
    }
    q.r[p] = r;
    q.z[p] = v[0].z + xi * z10 + eta * z20;
    q.area_weight[p] = area * ref.weight[p];
    q.weight[p] = q.area_weight[p] * (axisymmetric ? 2.0 * std::numbers::pi * r : depth);
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

namespace {

/// B = sum_i a_i G_i at one quadrature point of an M-node element.
template <int M>
std::array<double, 2> point_b(const double* g_r, const double* g_z, const double* a) {
  double br = 0.0, bz = 0.0;
  for (int i = 0; i < M; ++i) {
    br += a[i] * g_r[i];
    bz += a[i] * g_z[i];
  }
  return {br, bz};
}

/// Writes the summed residual and the tangent, whose lower triangle `k` holds, mirrored.
template <int M>
void store_residual_tangent(const double* res, const double* k, double* residual, double* tangent) {
  for (int i = 0; i < M; ++i) residual[i] = res[i];
  if (!tangent) return;
  for (int i = 0; i < M; ++i) {
    for (int j = 0; j <= i; ++j) tangent[i * M + j] = tangent[j * M + i] = k[i * M + j];
  }
}

/// element_residual_tangent for a fixed number of nodes M (loops unrolled by the compiler).
template <int M>
void residual_tangent(const ElementQuadrature& q, const double* a, const Reluctivity& law,
                      double* residual, double* tangent) {
  double res[M] = {}, k[M * M] = {};
  for (int p = 0; p < q.points; ++p) {
    const double* g_r = q.g_r[p].data();
    const double* g_z = q.g_z[p].data();
    const auto [br, bz] = point_b<M>(g_r, g_z, a);
    const double b2 = br * br + bz * bz;
    // One B-H curve evaluation for nu and its slope when the tangent is wanted.
    const auto [nu, dnu_db2] = tangent ? law.nu_and_dnu_db2(b2) : std::pair{law.nu(b2), 0.0};
    const double w = q.weight[p];
    double b_dot_g[M];
    for (int i = 0; i < M; ++i) {
      b_dot_g[i] = br * g_r[i] + bz * g_z[i];
      res[i] += w * nu * b_dot_g[i];
    }
    if (!tangent) continue;
    const double rank_one = 2.0 * dnu_db2;
    for (int i = 0; i < M; ++i) {
      for (int j = 0; j <= i; ++j) {  // lower triangle; mirrored when stored (K is symmetric)
        k[i * M + j] +=
            w * (nu * (g_r[i] * g_r[j] + g_z[i] * g_z[j]) + rank_one * b_dot_g[i] * b_dot_g[j]);
      }
    }
  }
  store_residual_tangent<M>(res, k, residual, tangent);
}

/// residual_tangent of a linear anisotropic law, H = diag(nu_r, nu_z) B: r_i = sum_q w H . G_i
/// and K_ij = sum_q w (nu_r G_i,r G_j,r + nu_z G_i,z G_j,z).
template <int M>
void anisotropic_residual_tangent(const ElementQuadrature& q, const double* a,
                                  const Reluctivity& law, double* residual, double* tangent) {
  const auto [nu_r, nu_z] = law.nu_axes();
  double res[M] = {}, k[M * M] = {};
  for (int p = 0; p < q.points; ++p) {
    const double* g_r = q.g_r[p].data();
    const double* g_z = q.g_z[p].data();
    const auto [br, bz] = point_b<M>(g_r, g_z, a);
    const double w = q.weight[p], hr = w * nu_r * br, hz = w * nu_z * bz;
    for (int i = 0; i < M; ++i) res[i] += hr * g_r[i] + hz * g_z[i];
    if (!tangent) continue;
    for (int i = 0; i < M; ++i) {
      for (int j = 0; j <= i; ++j)
        k[i * M + j] += w * (nu_r * g_r[i] * g_r[j] + nu_z * g_z[i] * g_z[j]);
    }
  }
  store_residual_tangent<M>(res, k, residual, tangent);
}

}  // namespace

void element_residual_tangent(const ElementQuadrature& q, const double* a, const Reluctivity& law,
                              double* residual, double* tangent) {
  if (law.anisotropic()) {
    if (q.nodes == 6) {
      anisotropic_residual_tangent<6>(q, a, law, residual, tangent);
    } else {
      anisotropic_residual_tangent<3>(q, a, law, residual, tangent);
    }
  } else if (q.nodes == 6) {
    residual_tangent<6>(q, a, law, residual, tangent);
  } else {
    residual_tangent<3>(q, a, law, residual, tangent);
  }
}

void element_source(const ElementQuadrature& q, double* source) {
  for (int i = 0; i < q.nodes; ++i) source[i] = 0.0;
  for (int p = 0; p < q.points; ++p) {
    for (int i = 0; i < q.nodes; ++i) source[i] += q.weight[p] * q.n[p][i];
  }
}

double element_stored_energy(const ElementQuadrature& q, const double* a, const Reluctivity& law) {
  double energy = 0.0;
  for (int p = 0; p < q.points; ++p) {
    const auto [br, bz] = element_b(q, p, a);
    energy += q.weight[p] * law.energy_density(br, bz);
  }
  return energy;
}

std::array<double, 2> element_energy(const ElementQuadrature& q, const double* a,
                                     const Reluctivity& law) {
  double energy = 0.0, b_dot_h = 0.0;
  for (int p = 0; p < q.points; ++p) {
    const auto [br, bz] = element_b(q, p, a);
    const auto [hr, hz] = law.h(br, bz);
    energy += q.weight[p] * law.energy_density(br, bz);
    b_dot_h += q.weight[p] * (hr * br + hz * bz);
  }
  return {energy, b_dot_h};
}

}  // namespace rheomag::magnetostatics
