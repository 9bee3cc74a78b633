// rheomag solve: magnetostatic solve of a TOML case or a FEMM .fem model.

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "case/case_file.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/memory_limit.hpp"
#include "figures/gap_theta.hpp"
#include "figures/solve_pictures.hpp"
#include "magnetostatics/femm_ans.hpp"
#include "magnetostatics/report.hpp"
#include "magnetostatics/solve_output.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "magnetostatics3d/report3d.hpp"
#include "magnetostatics3d/solve3d.hpp"
#include "plot/figure.hpp"

namespace {

using namespace rheomag::magnetostatics;
using namespace rheomag::cases;

struct SolveCommandOptions {
  std::string case_path;
  std::optional<double> current;
  std::vector<double> sweep;
  std::string vtk, ans, plot;  // .vtu, FEMM .ans, picture (.png / .svg)
  std::optional<int> order;
  std::vector<double> points;          // r1, z1, r2, z2, ... [m]
  std::vector<std::string> integrals;  // REGION:KIND
  std::vector<std::string> lines;      // x1,y1:x2,y2
  int line_points = 101;
  bool json = false, three_d = false, full = false;
  std::string mesher = "tetgen";
  std::string max_memory;  // --max-memory text ("8G"); empty: the default limit
};

void check_current(double current, const char* option) {
  if (!std::isfinite(current))
    throw rheomag::InputError(std::string(option) + ": expected a finite current in A");
}

/// `solve --3d`: the case revolved about z with its [[feature]] cuts (magnetostatics3d).
void run_3d(const SolveCommandOptions& o, const Case& c) {
  if (!o.sweep.empty() || o.order || !o.integrals.empty() || !o.lines.empty() || !o.ans.empty())
    throw rheomag::InputError(
        "--sweep, --order, --integral, --line and --ans are not available with --3d");
  namespace m3 = rheomag::magnetostatics3d;
  const m3::Mesher3d mesher = m3::kMesher3dNames.parse(o.mesher, "--mesher");
  m3::Solve3dOptions options =
      mesher == m3::Mesher3d::swept ? m3::swept_options() : m3::Solve3dOptions{};
  options.force_full = o.full;
  if (!o.max_memory.empty())
    options.max_memory = rheomag::parse_memory_size(o.max_memory, "--max-memory");
  if (!o.json) {
    options.progress = [](const rheomag::ProgressEvent& e) {
      std::cerr << "3d: " << e.stage << " (" << e.elapsed << " s)"
                << (e.detail.empty() ? "" : ": " + e.detail) << std::endl;
    };
  }
  const m3::Solve3dResult solved = m3::solve_problem_3d(c.problem, m3::read_features(c), options);
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

void run(const SolveCommandOptions& o) {
  if (!o.plot.empty() && !rheomag::plot::is_picture_path(o.plot))
    throw rheomag::InputError("--plot: expected a file name ending in .png or .svg");
  Case c = load_case(o.case_path);
  Problem& problem = c.problem;
  if (o.current) {
    check_current(*o.current, "--current");
    if (problem.circuits.empty())
      throw rheomag::InputError(o.case_path + ": --current given but the case has no circuit");
    for (Circuit& circuit : problem.circuits) circuit.current = *o.current;
  }
  if (o.three_d) {
    run_3d(o, c);
    return;
  }
  if (o.order) problem.order = *o.order;
  for (double i : o.sweep) check_current(i, "--sweep");
  if (!o.sweep.empty() && problem.circuits.empty())
    throw rheomag::InputError(o.case_path + ": --sweep given but the case has no circuit");

  rheomag::magnetostatics::SolveOptions options;
  if (!o.max_memory.empty())
    options.mesh.max_memory = rheomag::parse_memory_size(o.max_memory, "--max-memory");
  SolveResult solved = solve_problem(problem, options);
  SolveOutput out;
  out.case_name = c.name, out.case_path = o.case_path, out.description = c.description;
  out.mesh_seconds = solved.mesh_seconds;
  if (!o.sweep.empty()) out.sweep = solved.solver->sweep(0, o.sweep);
  if (!o.vtk.empty()) {
    write_results_vtu(o.vtk, *solved.solver, solved.solution, solved.results);
    out.files.emplace_back("vtk", o.vtk);
  }
  if (!o.ans.empty()) {
    rheomag::write_file_atomically(o.ans, femm_ans_text(*solved.solver, solved.solution));
    out.files.emplace_back("ans", o.ans);
  }
  if (!o.plot.empty()) {
    rheomag::figures::write_field_map(
        o.plot, "--plot", {c.name, *solved.solver, solved.solution, solved.results, out.sweep}, {});
    out.files.emplace_back("plot", o.plot);
  }
  out.probes = probe_field(*solved.solver, solved.solution, o.points);
  out.integrals = block_integrals(*solved.solver, solved.solution, o.integrals);
  for (const std::string& line : o.lines)
    out.lines.push_back(line_field(*solved.solver, solved.solution, line, o.line_points));
  if (o.json) {
    rheomag::app::print_json(solve_output_json(*solved.solver, solved.results, out), 2);
  } else {
    std::cout << solve_output_text(*solved.solver, solved.results, out);
  }
}

const bool solve_registered = rheomag::app::register_command([](CLI::App& root) {
  auto o = std::make_shared<SolveCommandOptions>();
  CLI::App* cmd = root.add_subcommand(
      "solve",
      "Solve the magnetostatic field of a valve (the FEMM step).\n"
      "CASE is a rheomag TOML case (docs/case-format.md) or a FEMM 4.2 .fem model (magnetostatic,\n"
      "axisymmetric or planar). Prints the flux density in every fluid gap (average/min/max of\n"
      "|B| and of its component normal to the gap walls, over the gap and along its mid-line),\n"
      "each circuit's flux linkage, secant and incremental inductance, and the stored energy.\n"
      "Exit codes: 0 success, 2 bad input, 3 Newton did not converge.");
  cmd->add_option("CASE", o->case_path, "Case file (.toml) or FEMM model (.fem)")->required();
  cmd->add_option("--current", o->current,
                  "Current of every circuit [A] (default: the currents in the case)");
  cmd->add_option("--sweep", o->sweep,
                  "Also tabulate lambda(I), L(I) of the first circuit at these currents [A], "
                  "e.g. --sweep 0,0.25,0.5,0.75,1")
      ->delimiter(',');
  cmd->add_option("--point", o->points,
                  "Also print the flux density at these points, r,z pairs in metres "
                  "(x,y for planar models), e.g. --point 0.01,0.02,0.015,0")
      ->delimiter(',');
  cmd->add_option("--integral", o->integrals,
                  "Also print a block integral REGION:KIND (repeatable; REGION+REGION for a body "
                  "of several): a_dot_j, energy, coenergy, area, volume, average_b, flux, force, "
                  "torque (docs/femm.md)");
  cmd->add_option("--line", o->lines,
                  "Also print B_n, B_t, |B|, H along the line x1,y1:x2,y2 [m] and the flux "
                  "through it (repeatable)");
  cmd->add_option("--points", o->line_points, "Points along each --line (default 101)")
      ->check(rheomag::app::in_domain(rheomag::Domain::between(2, 100000).whole()));
  cmd->add_option("--vtk", o->vtk, "Write mesh and fields (A, B, |B|, H, mu_r) to this .vtu file")
      ->check(rheomag::app::output_file());
  cmd->add_option("--ans", o->ans,
                  "Write FEMM 4.2's solution file (.ans: the model and A at the nodes, P2 "
                  "triangles split in four) for FEMM's or xfemm's post-processor")
      ->check(rheomag::app::output_file_in_writable_folder());
  cmd->add_option("--plot", o->plot,
                  "Draw the field map (|B|, flux lines, gaps; with --3d: each gap's B_avg_theta, "
                  "polar; docs/plots.md) to this .png or .svg file")
      ->check(rheomag::app::output_file_in_writable_folder());
  cmd->add_option("--order", o->order, "Lagrange element order, 1 or 2 (default: the case's, 2)")
      ->check(rheomag::app::in_domain(rheomag::Domain::between(1, 2).whole()));
  cmd->add_flag("--json", o->json, "Print one JSON object (SI units) instead of the summary");
  cmd->add_flag("--3d", o->three_d,
                "Revolve the case about z and solve in 3D with its [[feature]] cuts (lead_slot, "
                "hole, port, eccentricity; docs/magnetostatics3d.md)");
  cmd->add_flag("--full", o->full, "With --3d: mesh the whole revolution, no wedge or half model");
  cmd->add_option("--mesher", o->mesher,
                  "With --3d: \"tetgen\" (isotropic tetrahedra, default) or \"swept\" (the "
                  "meridian mesh swept through angles graded towards the features: much faster "
                  "for half and full models)")
      ->check(rheomag::app::non_empty());
  cmd->add_option(
         "--max-memory", o->max_memory,
         "Refuse, before meshing, a mesh (2D, or 3D with --3d) whose solve is estimated to need "
         "more memory than this: bytes with a K, M, G or T suffix (powers of 1024), "
         "e.g. 8G (default: 3/4 of the memory available: physical, ulimit -v, cgroup)")
      ->check(rheomag::app::non_empty());
  cmd->callback([o] { run(*o); });
});

}  // namespace
