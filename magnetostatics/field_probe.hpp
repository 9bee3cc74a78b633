#pragma once
// The flux density at given points of a solved field (`rheomag solve --point`), as values, a JSON
// array and text lines.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"

namespace rheomag::magnetostatics {

/// B at one point of the meridian (or planar) plane.
struct FieldProbe {
  double r = 0.0, z = 0.0;      ///< the point [m]
  double b_r = 0.0, b_z = 0.0;  ///< components [T]
  double b = 0.0;               ///< |B| [T]
};

/// B at the points r1, z1, r2, z2, ... [m]. InputError for an odd count or a point outside the
/// mesh (naming it).
std::vector<FieldProbe> probe_field(const MagnetostaticSolver& solver, const Solution& solution,
                                    const std::vector<double>& points);

/// The probes as a JSON array of {r, z, b_r, b_z, b}.
nlohmann::json probes_json(const std::vector<FieldProbe>& probes);

/// The probes as text: a blank line, then one line per point (nothing without probes).
std::string probes_text(const std::vector<FieldProbe>& probes);

}  // namespace rheomag::magnetostatics
