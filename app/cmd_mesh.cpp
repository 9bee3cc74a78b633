// rheomag mesh: mesh a case (no solve) and report the mesh quality; optionally write the .vtu.

#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/progress_lines.hpp"
#include "case/case_file.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "mesh/quality.hpp"
#include "mesh/vtu_writer.hpp"

namespace {

using namespace rheomag;

struct MeshCommandOptions {
  std::string case_path;
  std::vector<std::string> settings;  // --set KEY=VALUE
  std::string vtk;
  std::optional<int> order;
  bool json = false;
};

void run(const MeshCommandOptions& o) {
  cases::Case c = app::load_case(o.case_path, o.settings);
  if (o.order) c.problem.order = *o.order;
  // A mesh of hundreds of thousands of triangles takes a while: its progress after 2 s.
  magnetostatics::SolveOptions options;
  options.mesh.progress = app::progress_lines("mesh", std::cerr, 2.0, 2.0);
  const auto [closed, m] = magnetostatics::close_and_mesh(c.problem, options);
  const mesh::MeshQuality quality = mesh::measure_quality(m, closed.geometry);
  if (!o.vtk.empty()) {
    std::vector<std::string> names;
    for (const auto& region : closed.geometry.regions) names.push_back(region.name);
    mesh::write_vtu(o.vtk, m, {}, names);
  }
  if (o.json) {
    nlohmann::json j = mesh::quality_json(quality);
    j["case"] = c.name;
    if (!o.settings.empty()) j["set"] = o.settings;
    if (!o.vtk.empty()) j["vtk"] = o.vtk;
    rheomag::app::print_json(j, 2);
    return;
  }
  std::cout << "case " << c.name << " (" << o.case_path << ")\n";
  if (!o.settings.empty()) std::cout << c.description << "\n";  // the --set edits
  std::cout << mesh::format_quality(quality);
  if (!o.vtk.empty()) std::cout << "wrote " << o.vtk << "\n";
}

const bool mesh_registered = rheomag::app::register_command([](CLI::App& root) {
  auto o = std::make_shared<MeshCommandOptions>();
  CLI::App* cmd = root.add_subcommand(
      "mesh",
      "Mesh a case without solving it: CGAL constrained Delaunay triangulation with quality\n"
      "refinement, per-region sizes and at least `min_gap_elements` elements across every fluid\n"
      "gap. Prints element counts, minimum angle, aspect ratio and per-region statistics.");
  cmd->add_option("CASE", o->case_path, "Case file (.toml) or FEMM model (.fem)")->required();
  rheomag::app::add_set_option(cmd, o->settings);
  cmd->add_option("--vtk", o->vtk, "Write the mesh with region ids and names to this .vtu file")
      ->check(rheomag::app::output_file());
  cmd->add_option("--order", o->order, "Lagrange element order, 1 or 2 (default: the case's)")
      ->check(rheomag::app::in_domain(rheomag::Domain::between(1, 2).whole()));
  cmd->add_flag("--json", o->json, "Print the mesh statistics as one JSON object");
  cmd->callback([o] { run(*o); });
});

}  // namespace
