#pragma once
// Presenting a magnetostatic solve: JSON object, human-readable summary, and .vtu fields.

#include <nlohmann/json.hpp>
#include <string>

#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"
#include "mesh/vtu_writer.hpp"

namespace rheomag::magnetostatics {

/// The JSON object of `rheomag solve --json` (keys fixed by the CLI interface: gaps, flux_linkage,
/// inductance, incremental_inductance, energy, newton_iterations, dofs, elements, seconds,
/// circuits). `flux_linkage`/`inductance` are those of the first circuit (null without one).
nlohmann::json results_json(const MagnetostaticSolver& solver, const Results& results);

/// A plain-text summary of the same numbers for a terminal (units in mT, mH, ...).
std::string results_summary(const MagnetostaticSolver& solver, const Results& results);

/// Writes the mesh with region ids and names, A, B (vector), |B|, H (vector), |H| and mu_r to a
/// .vtu file (atomically), then the `extra` fields (e.g. a transient's eddy-current density).
/// Vectors are (B_r, B_z, 0) for axisymmetric problems.
void write_results_vtu(const std::string& path, const MagnetostaticSolver& solver,
                       const Solution& solution, const Results& results,
                       const mesh::VtuFields& extra = {});

}  // namespace rheomag::magnetostatics
