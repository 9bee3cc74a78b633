#include "magnetostatics/solve_problem.hpp"

#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "magnetostatics/domain.hpp"
#include "magnetostatics/nested_solve.hpp"

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

std::vector<mesh::Mesh> coarser_meshes(const cases::Problem& closed, std::size_t fine_nodes,
                                       const SolveOptions& options) {
  std::vector<mesh::Mesh> coarser;
  if (options.nested_above <= 0 || fine_nodes <= static_cast<std::size_t>(options.nested_above))
    return coarser;
  mesh::MeshOptions mesh_options = options.mesh;
  mesh_options.order = closed.order;
  mesh_options.min_gap_elements = closed.min_gap_elements;
  mesh_options.progress = nullptr;
  const double coarsest = 0.1 * static_cast<double>(options.nested_above);
  double scale = 1.0;
  for (double nodes = fine_nodes / 4.0; nodes >= coarsest; nodes /= 4.0) {
    scale *= 2.0;
    mesh_options.size_scale = options.mesh.size_scale * scale;
    coarser.insert(coarser.begin(), mesh::generate_mesh(closed.geometry, mesh_options));
  }
  return coarser;
}

SolveResult solve_problem(const cases::Problem& problem, const SolveOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  auto [closed, mesh] = close_and_mesh(problem, options);
  SolveResult result;
  result.mesh_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<mesh::Mesh> coarser = coarser_meshes(closed, mesh.nodes.size(), options);
  result.solver =
      std::make_unique<MagnetostaticSolver>(std::move(closed), std::move(mesh), options);
  if (coarser.empty()) {
    result.solution = result.solver->solve();
  } else {
    std::vector<double> currents;
    for (const auto& circuit : result.solver->problem().circuits)
      currents.push_back(circuit.current);
    result.solution = solve_nested(*result.solver, coarser, currents);
  }
  result.results = compute_results(*result.solver, result.solution);
  return result;
}

}  // namespace rheomag::magnetostatics
