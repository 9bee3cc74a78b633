#pragma once
// Closing the computational domain: the automatic outer boundary and the background air region.

#include "case/problem.hpp"

namespace rheomag::magnetostatics {

/// Number of straight segments of the automatic outer boundary (semicircle; a circle gets twice).
inline constexpr int kOuterArcSegments = 96;

/// Returns the problem with its outer boundary added, according to Problem::outer (the result's
/// `outer` is none: its PSLG contains the boundary):
/// - none: unchanged.
/// - open / dirichlet: a boundary of radius R0 = outer_radius_factor x R_b, where R_b is the
///   radius of the bounding circle of all PSLG points (axisymmetric: centred on the axis at the
///   middle of the z range; planar: centred on the bounding box). Axisymmetric: a semicircle in
///   r >= 0 plus the axis segments on r = 0 joining every point on the axis; planar: a circle.
///   Polygonal with kOuterArcSegments (x2 planar) chords.
///   `open` marks it with the asymptotic (dipole-decay) Robin condition: far from the sources
///   A_phi ~ sin(theta) / R^2, so on the sphere R = R0 the tangential field is
///   (n x H) . e_phi = nu0 A / R0, i.e. the mixed condition c0 = nu0 / R0, c1 = 0 (planar:
///   A_z ~ cos(theta) / R gives the same c0 = nu0 / R0). It adds the symmetric positive term
///   integral nu0 (A / R0) v 2 pi r ds to the weak form. `dirichlet` marks it A = 0.
/// - The faces reached by no seed become a new region "air" (material "air", mu_r = 1, reused if
///   the problem has a linear material of that name) unless geometry.default_region is already set.
/// Throws InputError if there is no geometry, a point has r < 0 (axisymmetric) or the factor is
/// not a finite number > 1.
cases::Problem close_domain(const cases::Problem& problem);

}  // namespace rheomag::magnetostatics
