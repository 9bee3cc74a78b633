#include "magnetostatics/solve_output.hpp"

#include "magnetostatics/report.hpp"
#include "magnetostatics/sweep_report.hpp"

namespace rheomag::magnetostatics {

namespace {

/// What a written file is, for the text summary.
std::string file_note(const std::string& key) {
  if (key == "vtk") return " (open it in ParaView)";
  if (key == "ans") return " (FEMM 4.2 solution)";
  if (key == "plot") return " (field map)";
  return "";
}

}  // namespace

nlohmann::json solve_output_json(const MagnetostaticSolver& solver, const Results& results,
                                 const SolveOutput& output) {
  nlohmann::json j = results_json(solver, results);
  j["case"] = output.case_name;
  j["mesh_seconds"] = output.mesh_seconds;
  for (const auto& [key, path] : output.files) j[key] = path;
  if (!output.probes.empty()) j["points"] = probes_json(output.probes);
  if (!output.sweep.empty()) j["sweep"] = sweep_json(output.sweep);
  if (!output.integrals.empty()) j["integrals"] = integrals_json(output.integrals);
  if (!output.lines.empty()) j["lines"] = lines_json(output.lines);
  return j;
}

std::string solve_output_text(const MagnetostaticSolver& solver, const Results& results,
                              const SolveOutput& output) {
  const cases::Problem& problem = solver.problem();
  std::string text = "case " + output.case_name + " (" + output.case_path + ")\n";
  if (!output.description.empty()) text += output.description + "\n";
  text += results_summary(solver, results);
  if (!output.sweep.empty()) text += sweep_text(output.sweep, problem.circuits.front().name);
  text += probes_text(output.probes) + integrals_text(output.integrals) +
          lines_text(output.lines, problem.symmetry);
  for (std::size_t i = 0; i < output.files.size(); ++i)
    text += (i == 0 ? "\nwrote " : "wrote ") + output.files[i].second +
            file_note(output.files[i].first) + "\n";
  return text;
}

}  // namespace rheomag::magnetostatics
