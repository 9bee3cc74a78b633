// rheomag solve: magnetostatic solve of a TOML case or a FEMM .fem model.

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/solve_command.hpp"
#include "case/case_file.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/memory_limit.hpp"
#include "figures/solve_pictures.hpp"
#include "magnetostatics/femm_ans.hpp"
#include "magnetostatics/report.hpp"
#include "magnetostatics/solve_output.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "plot/figure.hpp"

namespace {

using namespace rheomag::magnetostatics;
using namespace rheomag::cases;
using rheomag::app::SolveCommandOptions;

void check_current(double current, const char* option) {
  if (!std::isfinite(current))
    throw rheomag::InputError(std::string(option) + ": expected a finite current in A");
}

/// `solve --current I1,I2,..`: the case solved at each current in turn (one mesh, each solve
/// warm-started), one summary (text) or one document (JSON, under "solutions") per current.
/// The solve's settings from the options: the memory bound of the 2D mesh (--max-memory).
rheomag::magnetostatics::SolveOptions solve_options(const SolveCommandOptions& o) {
  rheomag::magnetostatics::SolveOptions options;
  if (!o.max_memory.empty())
    options.mesh.max_memory = rheomag::parse_memory_size(o.max_memory, "--max-memory");
  return options;
}

void run_currents(const SolveCommandOptions& o, const Case& c) {
  if (!o.vtk.empty() || !o.ans.empty() || !o.plot.empty() || !o.sweep.empty())
    throw rheomag::InputError(
        "--current with several values solves each in turn; --vtk, --ans, --plot and --sweep "
        "take one --current (for a table of lambda, L and the gap B against current use --sweep)");
  SolveResult solved = solve_problem(c.problem, solve_options(o));
  nlohmann::json documents = nlohmann::json::array();
  for (std::size_t k = 0; k < o.currents.size(); ++k) {
    const std::vector<double> currents(c.problem.circuits.size(), o.currents[k]);
    // The first current is the one solve_problem solved at.
    const Solution solution =
        k == 0 ? solved.solution : solved.solver->solve(currents, &solved.solution.a);
    const Results results = k == 0 ? solved.results : compute_results(*solved.solver, solution);
    SolveOutput out;
    out.case_name = c.name, out.case_path = o.case_path, out.description = c.description;
    out.mesh_seconds = k == 0 ? solved.mesh_seconds : 0.0;
    out.probes = probe_field(*solved.solver, solution, o.points);
    out.integrals = block_integrals(*solved.solver, solution, o.integrals);
    for (const std::string& line : o.lines)
      out.lines.push_back(line_field(*solved.solver, solution, line, o.line_points));
    if (o.json) {
      documents.push_back(solve_output_json(*solved.solver, results, out));
    } else {
      std::cout << (k == 0 ? "" : "\n") << "=== --current " << o.currents[k] << " A ===\n"
                << solve_output_text(*solved.solver, results, out);
    }
  }
  if (o.json)
    rheomag::app::print_json(
        {{"case", c.name}, {"set", o.settings}, {"currents", o.currents}, {"solutions", documents}},
        2);
}

void run(const SolveCommandOptions& o) {
  if (!o.plot.empty() && !rheomag::plot::is_picture_path(o.plot))
    throw rheomag::InputError("--plot: expected a file name ending in .png or .svg");
  Case c = rheomag::app::load_case(o.case_path, o.settings);
  Problem& problem = c.problem;
  for (double i : o.currents) check_current(i, "--current");
  if (!o.currents.empty()) {
    if (problem.circuits.empty())
      throw rheomag::InputError(o.case_path + ": --current given but the case has no circuit");
    for (Circuit& circuit : problem.circuits) circuit.current = o.currents.front();
  }
  if (o.three_d) {
    rheomag::app::run_solve_3d(o, c);
    return;
  }
  if (o.currents.size() > 1) {
    if (o.order) problem.order = *o.order;
    run_currents(o, c);
    return;
  }
  if (o.order) problem.order = *o.order;
  for (double i : o.sweep) check_current(i, "--sweep");
  if (!o.sweep.empty() && problem.circuits.empty())
    throw rheomag::InputError(o.case_path + ": --sweep given but the case has no circuit");

  SolveResult solved = solve_problem(problem, solve_options(o));
  SolveOutput out;
  out.case_name = c.name, out.case_path = o.case_path, out.description = c.description;
  out.mesh_seconds = solved.mesh_seconds;
  if (!o.sweep.empty()) out.sweep = sweep_with_gaps(*solved.solver, 0, o.sweep);
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
    nlohmann::json j = solve_output_json(*solved.solver, solved.results, out);
    if (!o.settings.empty()) j["set"] = o.settings;  // the edits the description names
    rheomag::app::print_json(j, 2);
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
  rheomag::app::add_set_option(cmd, o->settings);
  rheomag::app::add_quantities(
      cmd, "--current", o->currents, rheomag::QuantityKind::current,
      "Current of every circuit (default: the currents in the case); several, comma-separated, "
      "are solved in turn on one mesh, each warm-started (also with --3d), e.g. "
      "--current 0.5,1");
  rheomag::app::add_quantities(
      cmd, "--sweep", o->sweep, rheomag::QuantityKind::current,
      "Also tabulate lambda(I), L(I) of the first circuit and each gap's B_avg, B_max_midline "
      "and B_max_area (docs/quantities.md) at these currents, e.g. --sweep 0,0.25,0.5,0.75,1");
  rheomag::app::add_quantities(cmd, "--point", o->points, rheomag::QuantityKind::length,
                               "Also print the flux density at these points, r,z pairs (x,y "
                               "for planar models), e.g. --point 10mm,20mm,15mm,0");
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
  cmd->add_option("--linear-solver", o->linear_solver,
                  "With --3d: how each Newton step's linear system is solved: \"cholmod\" "
                  "(tree-cotree gauge, sparse Cholesky; default) or \"ams\" (all edges, "
                  "conjugate gradients preconditioned with hypre's AMS: far less memory; "
                  "docs/magnetostatics3d.md)")
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
