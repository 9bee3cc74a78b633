#pragma once
// Presenting a 3D solve: JSON object, human-readable summary and .vtu of the 3D field.

#include <nlohmann/json.hpp>
#include <string>

#include "magnetostatics3d/solve3d.hpp"

namespace rheomag::magnetostatics3d {

/// The JSON object of `rheomag solve --3d --json`: the 2D keys (gaps with B_avg, B_min, B_max,
/// Bn_avg, Bn_min, Bn_max; circuits; flux_linkage; inductance; energy; dofs; elements;
/// newton_iterations; seconds) plus dimension = 3, tetrahedra, model, and per gap volume and
/// B_avg_theta (36 sectors of 10 degrees from phi = 0).
nlohmann::json results_json_3d(const Results3d& results);

/// A plain-text summary of the same numbers (mT, mH, ...).
std::string results_summary_3d(const Results3d& results);

/// Writes the tetrahedra with region ids and names, B (vector), |B|, H (vector) and mu_r per
/// tetrahedron to a .vtu file (atomically).
void write_results_vtu_3d(const std::string& path, const Solve3dResult& solved);

}  // namespace rheomag::magnetostatics3d
