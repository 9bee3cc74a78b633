#pragma once
// The epsilon-constraint Pareto front of [optimise.pareto]: the objective is optimised while the
// second objective is constrained at levels between its two single-objective extremes, each
// level started on the line from the previous level's optimum to the second objective's. Format and
// method: docs/optimisation.md.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "optimise/report.hpp"
#include "optimise/spec.hpp"

namespace rheomag::optimise {

/// One level of the front.
struct ParetoPoint {
  double epsilon = 0.0;  ///< the limit on the second objective (SI)
  DesignReport design;   ///< optimum of the objective under that limit (and the spec's constraints)
  int fe_solves = 0;     ///< evaluations this level took
};

/// The front with its two single-objective end points.
struct ParetoFront {
  ParetoSpec pareto;
  DesignReport objective_alone;     ///< optimum of the objective (first end point)
  DesignReport second_alone;        ///< optimum of the second objective alone (other end point)
  std::vector<ParetoPoint> points;  ///< from the objective's optimum towards the second's
};

/// A single-objective optimiser: the optimum of `spec` from design `start` (file units), the
/// objective divided by `objective_scale` for the solver.
using OptimiseFrom = std::function<DesignReport(
    const OptimiseSpec& spec, const std::vector<double>& start, double objective_scale)>;

/// Sweeps the front of spec.pareto: the second objective alone from `objective_alone.x`, then
/// spec.pareto->points levels from its value at `objective_alone` to its own optimum (the first
/// level is `objective_alone` itself). `solves` counts evaluations so far (for fe_solves).
ParetoFront pareto_front(const OptimiseSpec& spec, const DesignReport& objective_alone,
                         const OptimiseFrom& optimise, const std::function<int()>& solves);

/// The spec optimising spec.pareto's quantity alone (its own sense; objective constraints kept).
OptimiseSpec second_objective_spec(const OptimiseSpec& spec);

/// pareto.csv: epsilon, objective, second, feasible, fe_solves, the design, every quantity.
std::string pareto_csv(const OptimiseSpec& spec, const ParetoFront& front);

/// Writes pareto.csv into `dir` (atomically) and, if gnuplot is on the PATH, pareto.png (the
/// front, second objective against the objective). Returns the files written.
std::vector<std::filesystem::path> write_pareto(const std::filesystem::path& dir,
                                                const OptimiseSpec& spec, const ParetoFront& front);

}  // namespace rheomag::optimise
