#pragma once
// How each region's circuit current spreads over it, as FEMM's magnetostatic solver spreads it.
//
// FEMM (fsolver: static2d.cpp, staticaxi.cpp) first turns every label of a series circuit into
// a circuit of its own carrying turns x current, then treats every circuit as parallel: a group
// of regions sharing a current I_G. The regions' own block current densities are taken back,
// I = I_G - sum J_block a, and then
//   - if no solid conductor of the group conducts: J = I / (total area), even over the group;
//   - else J = sigma g(x) I / D with D = sum over the solid conductors of sigma integral g dA,
//     g = 1 (planar) or 1/r (axisymmetric: the electric field of a voltage around the axis).
// As in FEMM, g is taken at each triangle's centroid: J is constant on a triangle, the group's
// current is exact on the mesh, and a solid conductor on the axis stays finite.
// A winding of N turns in a series circuit thus carries N I / area, as rheomag's TOML coils do.

#include <vector>

#include "case/problem.hpp"
#include "mesh/mesh.hpp"

namespace rheomag::magnetostatics {

/// One region's circuit current density on a triangle with centroid radius r:
/// J = g(r) (per_amp I_circuit + offset) on top of the region's fixed J; g = 1/r when `radial`.
struct RegionCurrent {
  double per_amp = 0.0;  ///< [A/m^2 per A], [A/m per A] when radial
  double offset = 0.0;   ///< [A/m^2], [A/m] when radial: the fixed block current taken back
  bool radial = false;   ///< J ~ 1/r (a solid conductor of an axisymmetric model)
  /// The current density factor g at a triangle's centroid radius r [m].
  double g(double r) const { return radial ? 1.0 / r : 1.0; }
  /// The added current density [A/m^2] on a triangle of centroid radius r for a circuit current.
  double density(double current, double r) const { return g(r) * (per_amp * current + offset); }
};

/// The circuit current densities of every region of `problem` (index as Problem::regions) on
/// `mesh`: regions outside circuits get zeros. `area[r]` is region r's meridian area [m^2].
std::vector<RegionCurrent> circuit_currents(const cases::Problem& problem, const mesh::Mesh& mesh,
                                            const std::vector<double>& area);

}  // namespace rheomag::magnetostatics
