#pragma once
// Element kernels of the magnetostatic weak form: one triangle's residual, tangent and load.
//
// Weak form (axisymmetric, unknown A = A_phi, B = curl(A e_phi)):
//   sum_e  integral  nu(|B|^2) B . B(v)  2 pi r dr dz  =  integral J v 2 pi r dr dz  (+ boundary)
// with B_r = -dA/dz, B_z = dA/dr + A/r. Planar (A = A_z): B_x = dA/dy, B_y = -dA/dx and the
// weight 2 pi r is replaced by the depth. Quadrature points are interior to the triangles, so
// A/r is evaluated at r > 0 only; on the axis A = 0 is imposed (A_phi is odd in r). A linear
// anisotropic law replaces nu(|B|^2) B by diag(nu_r, nu_z) B (FEMM's Mu_x != Mu_y).

#include <array>

#include "case/problem.hpp"
#include "magnetostatics/lagrange.hpp"
#include "magnetostatics/reluctivity.hpp"
#include "mesh/pslg.hpp"

namespace rheomag::magnetostatics {

/// One triangle's shape functions and B operators at its quadrature points: B = sum_i A_i G_i.
struct ElementQuadrature {
  int nodes = 3;   ///< nodes per element (3 or 6)
  int points = 0;  ///< quadrature points
  std::array<double, kMaxQuadraturePoints>
      weight{};  ///< dV weight: 2 pi r |T| w_q or depth |T| w_q
  std::array<double, kMaxQuadraturePoints> area_weight{};  ///< meridian area weight |T| w_q
  std::array<double, kMaxQuadraturePoints> r{}, z{};       ///< point coordinates [m]
  std::array<std::array<double, kMaxElementNodes>, kMaxQuadraturePoints> n{};  ///< N_i
  std::array<std::array<double, kMaxElementNodes>, kMaxQuadraturePoints>
      g_r{};  ///< G_i, r (x) part
  std::array<std::array<double, kMaxElementNodes>, kMaxQuadraturePoints>
      g_z{};  ///< G_i, z (y) part
};

/// B operator of a point given reference coordinates (xi, eta) in a triangle with vertices `v`:
/// fills n, g_r, g_z (size nodes). At r = 0 (axisymmetric) it uses the limit A/r -> dA/dr.
void b_operator(cases::Symmetry symmetry, int order, const std::array<mesh::Point, 3>& v, double xi,
                double eta, double* n, double* g_r, double* g_z);

/// Shape functions, B operators and weights of a triangle with vertices `v`.
void element_quadrature(cases::Symmetry symmetry, double depth, int order,
                        const std::array<mesh::Point, 3>& v, ElementQuadrature& q);

/// Flux density (B_r, B_z) [T] at quadrature point `p` for local nodal values `a`.
std::array<double, 2> element_b(const ElementQuadrature& q, int p, const double* a);

/// Internal-force residual r_i = sum_q w nu(|B|^2) B . G_i (no source), and when `tangent` is
/// not null the exact Jacobian K_ij = sum_q w [nu G_i . G_j + 2 nu'(|B|^2) (B . G_i)(B . G_j)]
/// (row-major, nodes x nodes); an anisotropic law's r_i = sum_q w H(B) . G_i, K its constant.
void element_residual_tangent(const ElementQuadrature& q, const double* a, const Reluctivity& law,
                              double* residual, double* tangent);

/// Source vector f_i = sum_q w N_i (per unit current density, J = 1 A/m^2).
void element_source(const ElementQuadrature& q, double* source);

/// Stored magnetic energy integral_V integral_0^B H dB dV of one triangle [J].
double element_stored_energy(const ElementQuadrature& q, const double* a, const Reluctivity& law);

/// Magnetic energy integral_V integral_0^B H dB dV and integral_V B . H dV of one triangle [J].
std::array<double, 2> element_energy(const ElementQuadrature& q, const double* a,
                                     const Reluctivity& law);

}  // namespace rheomag::magnetostatics
