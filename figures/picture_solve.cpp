#include "figures/picture_solve.hpp"

#include <cmath>

#include "core/error.hpp"

namespace rheomag::figures {

PictureSolve solve_for_pictures(cases::Case c, std::optional<double> current,
                                const std::vector<double>& currents, int points) {
  for (double i : currents) {
    if (!std::isfinite(i)) throw InputError("--currents: expected finite currents in A");
  }
  if (current && !std::isfinite(*current))
    throw InputError("--current: expected a finite current in A");
  const bool circuit = !c.problem.circuits.empty();
  if (!circuit && (current || !currents.empty()))
    throw InputError(c.name + ": --current/--currents given but the case has no circuit");
  if (current) {
    for (cases::Circuit& k : c.problem.circuits) k.current = *current;
  }
  PictureSolve out;
  out.name = c.name;
  out.solved = magnetostatics::solve_problem(c.problem);
  if (!circuit) return out;
  std::vector<double> sweep = currents;
  if (sweep.empty()) {
    const double first = c.problem.circuits.front().current;
    const double top = first != 0.0 ? 1.5 * first : 1.0;
    for (int k = 0; k < points; ++k) sweep.push_back(top * k / std::max(1, points - 1));
  }
  out.sweep = out.solved.solver->sweep(0, sweep);
  return out;
}

}  // namespace rheomag::figures
