#include "optimise/continuous.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace rheomag::optimise {

namespace {
constexpr int kRestarts = 2;  // Ipopt restarts after a failed fresh-mesh check

// Evaluates `x` on a fresh mesh (the mesh `rheomag solve` of the design makes) and records it.
DesignReport fresh_mesh_report(OptimiseEvaluator& evaluator, const OptimiseSpec& spec,
                               const std::vector<double>& x, const std::string& purpose,
                               std::vector<HistoryRow>& history) {
  evaluator.remesh_next();
  HistoryRow row;
  row.purpose = purpose;
  row.x = x;
  row.q = evaluator.evaluate(x);
  history.push_back(row);
  return report_design(spec, x, row.q);
}
}  // namespace

bool is_strict_vertex(const OptimiseSpec& spec, const NlpResult& solved) {
  if (solved.bound_multipliers.size() != spec.variables.size() || !solved.converged) return false;
  for (std::size_t i = 0; i < spec.variables.size(); ++i) {
    const auto& v = spec.variables[i];
    const double z = solved.bound_multipliers[i], near = 1e-6 * (v.upper - v.lower);
    const bool pressed = (z >= kVertexMultiplier && solved.x[i] <= v.lower + near) ||
                         (z <= -kVertexMultiplier && solved.x[i] >= v.upper - near);
    if (!pressed) return false;
  }
  return true;
}

ContinuousOptimum optimise_continuous(OptimiseEvaluator& evaluator, const OptimiseSpec& spec,
                                      const std::vector<double>& start,
                                      const design::Quantities* start_q, double objective_scale,
                                      const IpoptSettings& settings,
                                      std::vector<HistoryRow>& history) {
  ScaledProgram program(
      spec,
      [&evaluator](const std::vector<double>& x, bool neighbour) {
        return evaluator.evaluate(x, neighbour);
      },
      objective_scale, history);
  if (start_q) program.seed(start, *start_q, "initial");
  ContinuousOptimum out;
  std::vector<double> from = start;
  // Ipopt on the morphed mesh; the optimum is then checked on a fresh mesh of its own geometry.
  // If that check violates a constraint (morphed and fresh mesh differ by the discretisation
  // error), Ipopt restarts from the optimum with the fresh mesh as the new morph reference.
  for (int pass = 0; pass <= kRestarts; ++pass) {
    const NlpResult solved = program.solve(from, settings);
    out.status = solved.status;
    out.converged = solved.converged;
    out.infeasible = solved.infeasible;
    out.iterations += solved.iterations;
    program.forget();
    out.report = fresh_mesh_report(evaluator, spec, solved.x, "fresh_mesh", history);
    out.report.strict_vertex = is_strict_vertex(spec, solved);
    if (out.report.feasible || solved.infeasible) break;
    from = solved.x;
  }
  return out;
}

DesignReport round_counts(OptimiseEvaluator& evaluator, const OptimiseSpec& spec,
                          const DesignReport& design, std::vector<HistoryRow>& history) {
  std::vector<std::size_t> counts;
  for (std::size_t i = 0; i < design.x.size(); ++i)
    if ((spec.variables[i].target.target == cases::KeyTarget::template_parameter &&
         spec.variables[i].target.kind == cases::ParameterKind::count) ||
        spec.variables[i].target.target == cases::KeyTarget::wire_gauge)
      counts.push_back(i);
  if (counts.empty()) return design;
  evaluator.exact_winding(true);  // candidates as their written cases have them
  std::optional<DesignReport> chosen;
  std::vector<std::vector<double>> tried;
  for (int mode = 0; mode < 3; ++mode) {
    std::vector<double> x = design.x;
    for (std::size_t i : counts) {
      const double v = mode == 0   ? std::round(x[i])
                       : mode == 1 ? std::floor(x[i])
                                   : std::ceil(x[i]);
      x[i] = std::clamp(v, std::ceil(spec.variables[i].lower), std::floor(spec.variables[i].upper));
    }
    // Rounded is floor or ceiling for a single count: each design is solved once.
    if (std::find(tried.begin(), tried.end(), x) != tried.end()) continue;
    tried.push_back(x);
    DesignReport candidate = fresh_mesh_report(evaluator, spec, x, "rounding", history);
    if (!chosen || better_design(candidate, *chosen, spec.maximise)) chosen = std::move(candidate);
  }
  if (tried.back() != chosen->x) {  // the chosen design's field for the .vtu
    evaluator.remesh_next();
    evaluator.evaluate(chosen->x);
  }
  evaluator.exact_winding(false);
  return *chosen;
}

}  // namespace rheomag::optimise
