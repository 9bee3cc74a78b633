#pragma once
// Lagrange P1/P2 shape functions on the reference triangle and the quadrature rules used with them.

#include <array>
#include <vector>

namespace rheomag::magnetostatics {

/// Largest number of nodes of a triangle (P2) and of quadrature points per triangle.
inline constexpr int kMaxElementNodes = 6;
inline constexpr int kMaxQuadraturePoints = 7;

/// A quadrature point of the reference triangle {xi, eta >= 0, xi + eta <= 1}.
struct TriangleQuadraturePoint {
  double xi = 0.0;
  double eta = 0.0;
  double weight = 0.0;  ///< fraction of the triangle area (the weights sum to 1)
};

/// Quadrature for Lagrange order `order`: P1 the 6-point degree-4 rule, P2 the 7-point degree-5
/// rule (Dunavant 1985 / Radon). All points are interior, so 1/r is finite on every element that
/// touches the axis.
const std::vector<TriangleQuadraturePoint>& triangle_quadrature(int order);

/// Shape functions of order 1 (3 nodes) or 2 (6 nodes: vertices, then midpoints of the edges
/// v0v1, v1v2, v2v0) at reference point (xi, eta): values and derivatives in xi and eta.
void lagrange_basis(int order, double xi, double eta, double* value, double* d_xi, double* d_eta);

/// A Gauss point on the reference edge [0, 1].
struct EdgeQuadraturePoint {
  double t = 0.0;
  double weight = 0.0;  ///< fraction of the edge length (the weights sum to 1)
};

/// 3-point Gauss-Legendre rule on [0, 1] (degree 5).
const std::vector<EdgeQuadraturePoint>& edge_quadrature();

/// Edge shape functions at t in [0, 1]: order 1 (end a, end b), order 2 (end a, end b, midpoint).
void edge_basis(int order, double t, double* value);

}  // namespace rheomag::magnetostatics
