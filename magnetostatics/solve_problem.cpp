#include "magnetostatics/solve_problem.hpp"

#include <chrono>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "magnetostatics/domain.hpp"

namespace rheomag::magnetostatics {

std::pair<cases::Problem, mesh::Mesh> close_and_mesh(const cases::Problem& problem,
                                                     const SolveOptions& options) {
  if (problem.order != 1 && problem.order != 2) {
    throw InputError(problem.geometry.source + ": element order " + std::to_string(problem.order) +
                     "; expected 1 or 2");
  }
  if (problem.regions.size() != problem.geometry.regions.size()) {
    throw InputError(problem.geometry.source + ": " + std::to_string(problem.regions.size()) +
                     " region data for " + std::to_string(problem.geometry.regions.size()) +
                     " regions");
  }
  cases::Problem closed = close_domain(problem);
  mesh::MeshOptions mesh_options = options.mesh;
  mesh_options.order = closed.order;
  mesh_options.min_gap_elements = closed.min_gap_elements;
  mesh::Mesh mesh = mesh::generate_mesh(closed.geometry, mesh_options);
  return {std::move(closed), std::move(mesh)};
}

std::unique_ptr<MagnetostaticSolver> make_solver(const cases::Problem& problem,
                                                 const SolveOptions& options) {
  auto [closed, mesh] = close_and_mesh(problem, options);
  return std::make_unique<MagnetostaticSolver>(std::move(closed), std::move(mesh), options);
}

SolveResult solve_problem(const cases::Problem& problem, const SolveOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  auto [closed, mesh] = close_and_mesh(problem, options);
  SolveResult result;
  result.mesh_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.solver =
      std::make_unique<MagnetostaticSolver>(std::move(closed), std::move(mesh), options);
  result.solution = result.solver->solve();
  result.results = compute_results(*result.solver, result.solution);
  return result;
}

}  // namespace rheomag::magnetostatics
