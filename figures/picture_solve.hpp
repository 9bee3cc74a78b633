#pragma once
// A case solved for its pictures: the field at the chosen current and the flux linkage swept
// over a current range (what `rheomag plot` and `rheomag report` draw).

#include <optional>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "figures/solve_pictures.hpp"
#include "magnetostatics/solve_problem.hpp"

namespace rheomag::figures {

/// A solve and the lambda(I) sweep of its first circuit.
struct PictureSolve {
  std::string name;
  magnetostatics::SolveResult solved;
  std::vector<magnetostatics::SweepPoint> sweep;  ///< empty without a circuit
  /// The view the picture writers take.
  SolvedCase view() const { return {name, *solved.solver, solved.solution, solved.results, sweep}; }
};

/// Solves `c` with every circuit at `current` (none: the case's currents), then sweeps lambda(I)
/// of the first circuit at `currents` (empty: `points` currents from 0 to 1.5 times the case's
/// first current, or to 1 A when that is 0). InputError (naming --current / --currents) for a
/// non-finite current, or for currents given to a case without a circuit.
PictureSolve solve_for_pictures(cases::Case c, std::optional<double> current,
                                const std::vector<double>& currents, int points);

}  // namespace rheomag::figures
