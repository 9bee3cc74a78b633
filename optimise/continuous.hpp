#pragma once
// One continuous FE optimisation: Ipopt on the morphed mesh from a start design, the optimum
// checked on a fresh mesh of its own geometry (restart if a constraint fails there); then
// template counts (turns) rounded to whole numbers and re-checked.

#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "optimise/evaluate.hpp"
#include "optimise/ipopt.hpp"
#include "optimise/problem.hpp"
#include "optimise/report.hpp"

namespace rheomag::optimise {

/// A continuous optimum (on a fresh mesh) and how Ipopt got there.
struct ContinuousOptimum {
  DesignReport report;
  std::string status;  ///< Ipopt's return status of the last pass
  bool converged = false;
  bool infeasible = false;  ///< Ipopt detected an infeasible problem
  int iterations = 0;
};

/// Optimises `spec` on `evaluator` from `start` (file units; `start_q`, if given, are its
/// quantities, so it is not solved again). Evaluations are appended to `history`.
ContinuousOptimum optimise_continuous(OptimiseEvaluator& evaluator, const OptimiseSpec& spec,
                                      const std::vector<double>& start,
                                      const design::Quantities* start_q, double objective_scale,
                                      const IpoptSettings& settings,
                                      std::vector<HistoryRow>& history);

/// Whether Ipopt's (converged) solution of `spec`'s scaled program has every variable on the
/// bound its multiplier presses on by at least kVertexMultiplier (DesignReport::strict_vertex).
bool is_strict_vertex(const OptimiseSpec& spec, const NlpResult& solved);

/// The design with every template count of `c` (e.g. geometry.turns) and the wire gauge rounded
/// (the gauge's candidates evaluated with the case's own whole turns): all to the
/// nearest, all down, all up, each distinct design checked on a fresh mesh; the best (feasible
/// first) wins.
/// Returns `design` unchanged if there is no count. Afterwards the evaluator's last field is the
/// returned design's.
DesignReport round_counts(OptimiseEvaluator& evaluator, const OptimiseSpec& spec,
                          const DesignReport& design, std::vector<HistoryRow>& history);

}  // namespace rheomag::optimise
