#include "magnetostatics/nested_solve.hpp"

#include "core/error.hpp"
#include "magnetostatics/prolongation.hpp"

namespace rheomag::magnetostatics {

Solution solve_nested(MagnetostaticSolver& fine, const std::vector<mesh::Mesh>& coarser,
                      const std::vector<double>& currents, const NestedOptions& options) {
  SolveOptions coarse_options = fine.options();
  coarse_options.incremental_inductance = false;
  coarse_options.newton.relative_tolerance = options.coarse_tolerance;
  Eigen::VectorXd a;
  const mesh::Mesh* previous = nullptr;
  try {
    for (const mesh::Mesh& m : coarser) {
      MagnetostaticSolver level(fine.problem(), m, coarse_options);
      const Eigen::VectorXd start =
          previous ? interpolate_nodal(*previous, a, m) : Eigen::VectorXd();
      a = level.solve(currents, previous ? &start : nullptr).a;
      previous = &m;
    }
  } catch (const ConvergenceError&) {
    previous = nullptr;  // a coarse mesh too coarse for Newton: the fine solve from A = 0
  }
  if (!previous) return fine.solve(currents);
  const Eigen::VectorXd start = interpolate_nodal(*previous, a, fine.mesh());
  return fine.solve(currents, &start);
}

}  // namespace rheomag::magnetostatics
