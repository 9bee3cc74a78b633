#pragma once
// Nested iteration: the nonlinear problem solved on coarser meshes of the same geometry first,
// each solution interpolated onto the next mesh as Newton's start, the fine mesh last.

#include <vector>

#include "magnetostatics/solver.hpp"
#include "mesh/mesh.hpp"

namespace rheomag::magnetostatics {

/// Settings of the coarse levels of a nested solve.
struct NestedOptions {
  /// Newton's relative residual on the coarse meshes: their solutions only start the next level,
  /// whose discretisation differs by more than this (pot core, 1e6 unknowns: the fine Newton
  /// history was the same to three digits with 1e-4 and 1e-2).
  double coarse_tolerance = 1e-2;
};

/// Solves `fine`'s problem at `currents` on each mesh of `coarser` (coarsest first; a solver per
/// mesh, built with fine's options but no dlambda/dI), each started from the previous solution
/// interpolated (prolongation.hpp), then `fine` from the last one. The result is fine's solution
/// to its own tolerance; only its Newton start differs from a plain fine.solve(currents). When a
/// coarse solve does not converge, the fine solve starts from A = 0. InputError as fine.solve.
Solution solve_nested(MagnetostaticSolver& fine, const std::vector<mesh::Mesh>& coarser,
                      const std::vector<double>& currents, const NestedOptions& options = {});

}  // namespace rheomag::magnetostatics
