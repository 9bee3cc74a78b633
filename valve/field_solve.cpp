// Mesh, solver and per-current solves of a device case (field_solve.hpp).

#include "valve/field_solve.hpp"

#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "magnetostatics/domain.hpp"
#include "mesh/mesher.hpp"

namespace rheomag::valve {

std::unique_ptr<magnetostatics::MagnetostaticSolver> make_device_solver(const cases::Case& c) {
  // As magnetostatics::solve_problem, without its solve at the case's currents.
  cases::Problem closed = magnetostatics::close_domain(c.problem);
  mesh::MeshOptions mesh_options;
  mesh_options.order = closed.order;
  mesh_options.min_gap_elements = closed.min_gap_elements;
  mesh::Mesh mesh = mesh::generate_mesh(closed.geometry, mesh_options);
  return std::make_unique<magnetostatics::MagnetostaticSolver>(std::move(closed), std::move(mesh));
}

DeviceField solve_at_current(magnetostatics::MagnetostaticSolver& solver, double current) {
  if (!std::isfinite(current)) throw InputError("currents must be finite");
  const std::size_t circuits = solver.problem().circuits.size();
  std::vector<double> per_circuit(circuits, 0.0);
  for (std::size_t k = 1; k < circuits; ++k) per_circuit[k] = solver.problem().circuits[k].current;
  if (circuits > 0) per_circuit[0] = current;
  DeviceField field;
  field.solution = solver.solve(per_circuit);
  field.results = magnetostatics::compute_results(solver, field.solution);
  return field;
}

}  // namespace rheomag::valve
