#pragma once
// One call from a Problem to results: close the domain, mesh, solve, post-process.

#include <memory>
#include <utility>
#include <vector>

#include "case/problem.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"
#include "mesh/mesher.hpp"

namespace rheomag::magnetostatics {

/// Everything solve_problem produces. The solver is kept (it owns the closed problem and the
/// mesh) so more currents or a sweep can be solved with the same factorisation analysis.
struct SolveResult {
  std::unique_ptr<MagnetostaticSolver> solver;
  Solution solution;
  Results results;
  double mesh_seconds = 0.0;  ///< time spent closing the domain and meshing
};

/// The problem closed (outer boundary, air) and meshed as solve_problem does (order
/// Problem::order, Problem::min_gap_elements); InputError for an order other than 1 or 2.
std::pair<cases::Problem, mesh::Mesh> close_and_mesh(const cases::Problem& problem,
                                                     const SolveOptions& options = {});

/// close_domain -> mesh::generate_mesh (order Problem::order, Problem::min_gap_elements) ->
/// MagnetostaticSolver, without a solve (for callers that choose their own currents).
std::unique_ptr<MagnetostaticSolver> make_solver(const cases::Problem& problem,
                                                 const SolveOptions& options = {});

/// The coarser copies of a closed problem's mesh with `fine_nodes` nodes that solve_problem solves
/// first (coarsest first, sizes x2, x4, ...; SolveOptions::nested_above); empty for a mesh at
/// or under that bound.
std::vector<mesh::Mesh> coarser_meshes(const cases::Problem& closed, std::size_t fine_nodes,
                                       const SolveOptions& options);

/// close_domain -> mesh::generate_mesh (order Problem::order, Problem::min_gap_elements) ->
/// MagnetostaticSolver -> solve at the Problem's circuit currents (by nested iteration above
/// SolveOptions::nested_above nodes) -> compute_results.
/// Throws InputError for bad input and ConvergenceError if Newton fails.
SolveResult solve_problem(const cases::Problem& problem, const SolveOptions& options = {});

}  // namespace rheomag::magnetostatics
