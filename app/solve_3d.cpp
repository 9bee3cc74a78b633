// `rheomag solve --3d`: the case revolved about z and solved in 3D (magnetostatics3d).

#include <iostream>

#include "app/command.hpp"
#include "app/solve_command.hpp"
#include "core/error.hpp"
#include "core/memory_limit.hpp"
#include "figures/gap_theta.hpp"
#include "magnetostatics3d/report3d.hpp"
#include "magnetostatics3d/solve3d.hpp"

namespace rheomag::app {
namespace {

/// `solve --3d --current I1,I2,..`: `solved` (at I1) solved again at each further current on its
/// mesh; one summary per current, or one JSON document with them under "solutions".
void print_currents_3d(const SolveCommandOptions& o, const cases::Case& c,
                       magnetostatics3d::Solve3dResult& solved) {
  namespace m3 = rheomag::magnetostatics3d;
  nlohmann::json documents = nlohmann::json::array();
  for (std::size_t k = 0; k < o.currents.size(); ++k) {
    if (k > 0 && !o.json) std::cerr << "3d: --current " << o.currents[k] << " A" << std::endl;
    const m3::Results3d& results =
        k == 0 ? solved.results : m3::solve_again_at_current_3d(solved, o.currents[k]);
    if (o.json) {
      nlohmann::json j = m3::results_json_3d(results);
      j["mesh_seconds"] = k == 0 ? solved.mesh_seconds : 0.0;
      documents.push_back(std::move(j));
      continue;
    }
    if (k == 0) {
      std::cout << "case " << c.name << " (" << o.case_path << ")\n";
      if (!c.description.empty()) std::cout << c.description << "\n";
    }
    std::cout << "\n=== --current " << o.currents[k] << " A ===\n"
              << m3::results_summary_3d(results);
  }
  if (o.json)
    print_json(
        {{"case", c.name}, {"set", o.settings}, {"currents", o.currents}, {"solutions", documents}},
        2);
}

}  // namespace

void run_solve_3d(const SolveCommandOptions& o, const cases::Case& c) {
  if (!o.sweep.empty() || o.order || !o.integrals.empty() || !o.lines.empty() || !o.ans.empty())
    throw rheomag::InputError(
        "--sweep, --order, --integral, --line and --ans are not available with --3d");
  namespace m3 = rheomag::magnetostatics3d;
  const m3::Mesher3d mesher = m3::kMesher3dNames.parse(o.mesher, "--mesher");
  m3::Solve3dOptions options =
      mesher == m3::Mesher3d::swept ? m3::swept_options() : m3::Solve3dOptions{};
  options.force_full = o.full;
  options.linear = m3::kLinearSolver3dNames.parse(o.linear_solver, "--linear-solver");
  if (!o.max_memory.empty())
    options.max_memory = rheomag::parse_memory_size(o.max_memory, "--max-memory");
  if (!o.json) {
    options.progress = [](const rheomag::ProgressEvent& e) {
      std::cerr << "3d: " << e.stage << " (" << e.elapsed << " s)"
                << (e.detail.empty() ? "" : ": " + e.detail) << std::endl;
    };
  }
  if (o.currents.size() > 1 && (!o.vtk.empty() || !o.plot.empty()))
    throw rheomag::InputError(
        "--current with several values solves each in turn; --vtk and --plot take one --current");
  m3::Solve3dResult solved = m3::solve_problem_3d(c.problem, m3::read_features(c), options);
  if (o.currents.size() > 1) {
    print_currents_3d(o, c, solved);
    return;
  }
  if (!o.vtk.empty()) m3::write_results_vtu_3d(o.vtk, solved);
  if (!o.plot.empty())
    rheomag::figures::gap_theta_figure(solved.results, c.name, 800, 700).write(o.plot, "--plot");
  if (o.json) {
    nlohmann::json j = m3::results_json_3d(solved.results);
    j["case"] = c.name;
    j["mesh_seconds"] = solved.mesh_seconds;
    if (!o.vtk.empty()) j["vtk"] = o.vtk;
    if (!o.plot.empty()) j["plot"] = o.plot;
    rheomag::app::print_json(j, 2);
    return;
  }
  std::cout << "case " << c.name << " (" << o.case_path << ")\n";
  if (!c.description.empty()) std::cout << c.description << "\n";
  std::cout << m3::results_summary_3d(solved.results);
  if (!o.vtk.empty()) std::cout << "\nwrote " << o.vtk << " (open it in ParaView)\n";
  if (!o.plot.empty()) std::cout << "wrote " << o.plot << " (B_avg_theta of each gap)\n";
}

}  // namespace rheomag::app
