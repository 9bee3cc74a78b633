#include "sweep/evaluate.hpp"

#include <cstdio>

#include "core/error.hpp"
#include "magnetostatics/report.hpp"

namespace rheomag::sweep {

std::vector<cases::CaseEdit> design_edits(const SweepSpec& spec, const Design& design) {
  std::vector<cases::CaseEdit> edits;
  for (std::size_t a = 0; a < spec.axes.size(); ++a)
    edits.push_back({spec.axes[a].key, design.values[a]});
  return edits;
}

std::filesystem::path design_vtu_path(const std::filesystem::path& vtu_dir, long long id) {
  char name[48];
  std::snprintf(name, sizeof name, "design-%06lld.vtu", id);
  return vtu_dir / name;
}

SweepEvaluator::SweepEvaluator(const SweepSpec& spec, const RowLayout& layout,
                               std::filesystem::path vtu_dir)
    : spec_(&spec),
      layout_(&layout),
      vtu_dir_(std::move(vtu_dir)),
      evaluator_(design::MeshPolicy::cached) {}

std::string SweepEvaluator::row(const Design& design) {
  try {
    return solve_row(design);
  } catch (const InputError& e) {
    return layout_->error_row(design, e.what());
  } catch (const ConvergenceError& e) {
    return layout_->error_row(design, std::string("did not converge: ") + e.what());
  } catch (const std::exception& e) {
    return layout_->error_row(design, std::string("internal error: ") + e.what());
  }
}

std::string SweepEvaluator::solve_row(const Design& design) {
  // Every design is validated exactly as a case file would be.
  const cases::Case design_case = cases::with(spec_->base, design_edits(*spec_, design));
  std::vector<double> currents;
  for (const cases::Circuit& circuit : design_case.problem.circuits)
    currents.push_back(circuit.current);
  // The same values apart from the currents: same problem and mesh, only the currents differ.
  std::vector<cases::KeyValue> values;
  for (std::size_t a = 0; a < spec_->axes.size(); ++a)
    if (spec_->axes[a].key.target != cases::KeyTarget::circuit_current)
      values.push_back(design.values[a]);
  const bool same_problem = evaluator_.last().solver && values == solver_values_;
  if (!same_problem) solver_values_ = values;
  const design::EvaluatedField& field = evaluator_.solve(design_case, currents, same_problem);
  const SolvedDesign solved{design_case, *field.solver, field.solution, field.results};
  std::string line = layout_->ok_row(design, solved);
  if (!vtu_dir_.empty()) {
    magnetostatics::write_results_vtu(design_vtu_path(vtu_dir_, design.id).string(), *field.solver,
                                      field.solution, field.results);
  }
  return line;
}

}  // namespace rheomag::sweep
