#pragma once
// A closed axisymmetric problem revolved about the z axis into a 3D piecewise linear complex.

#include <vector>

#include "case/problem.hpp"
#include "magnetostatics3d/plc.hpp"

namespace rheomag::magnetostatics3d {

/// Angular discretisation of a revolution about z: the planar facets of every surface of
/// revolution span consecutive angles of `angles` [rad], ascending from 0. `full`: the last
/// angle is 2 pi and wraps to 0; otherwise the model is the wedge [0, angles.back()] whose two
/// meridian end planes are symmetry planes (B tangent to them).
struct Revolution {
  std::vector<double> angles;
  bool full = true;
};

/// Angles of a revolution over [0, span] (span = 2 pi: full) with at most `max_step` [rad]
/// between consecutive angles and every angle of `breaks` (in [0, span]) among them.
Revolution make_revolution(double span, double max_step, std::vector<double> breaks = {});

/// Revolves `closed` (an axisymmetric problem with its outer boundary, see
/// magnetostatics::close_domain): every PSLG segment becomes planar trapezoids (triangles at the
/// axis) between consecutive angles; segments with a boundary condition become FaceKind::outer,
/// wedge end planes FaceKind::symmetry and every angle in `walls` a meridian facet holding the
/// whole PSLG (so that regions can differ between angular intervals). Region seeds are placed in
/// every angular interval with the volume limit `max_volume[region]` (0 = none); the region of
/// seed (region, interval) is `interval_region(region, interval)`.
Plc revolve(const cases::Problem& closed, const Revolution& revolution,
            const std::vector<double>& max_volume, const std::vector<double>& walls = {});

/// Index of the angular interval of `revolution` that contains angle `phi` (any real).
int interval_of(const Revolution& revolution, double phi);

}  // namespace rheomag::magnetostatics3d
