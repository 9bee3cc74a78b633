// rheomag plot: the pictures of a magnetostatic solve (field map, B along the gaps, lambda(I)).

#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "case/case_file.hpp"
#include "core/error.hpp"
#include "figures/picture_solve.hpp"

namespace {

using namespace rheomag;

struct PlotCommandOptions {
  std::string case_path;
  std::vector<std::string> settings;  // --set KEY=VALUE
  std::string out;
  std::optional<double> current;
  std::vector<double> currents;
  figures::FieldMapOptions map;
  int sweep_points = 11;
};

void run(const PlotCommandOptions& o) {
  const figures::PictureSolve solved = figures::solve_for_pictures(
      app::load_case(o.case_path, o.settings), o.current, o.currents, o.sweep_points);
  for (const auto& path : figures::write_solve_pictures(o.out, solved.view(), o.map))
    std::cout << "wrote " << path.string() << "\n";
}

const bool plot_registered = app::register_command([](CLI::App& root) {
  auto o = std::make_shared<PlotCommandOptions>();
  CLI::App* cmd = root.add_subcommand(
      "plot",
      "Draw a case's magnetostatic solution (docs/plots.md), as SVG and PNG, no display needed:\n"
      "field_map (|B| density zoomed to the device, flux lines, region outlines, gap names,\n"
      "colour bar), gap_NAME (B_n, B_t along each fluid gap on its mid-line and walls) and, with\n"
      "a circuit, lambda_L (flux linkage and inductances against the current).\n"
      "Exit codes: 0 success, 2 bad input, 3 Newton did not converge.");
  cmd->add_option("CASE", o->case_path, "Case file (.toml) or FEMM model (.fem)")->required();
  cmd->add_option("--out", o->out, "Folder to write the pictures into (created if absent)")
      ->required()
      ->check(app::non_empty());
  app::add_set_option(cmd, o->settings);
  app::add_quantity(cmd, "--current", o->current, QuantityKind::current,
                    "Current of every circuit for the field pictures (default: the case's)");
  app::add_quantities(cmd, "--currents", o->currents, QuantityKind::current,
                      "Currents of the lambda(I), L(I) picture, e.g. 0,0.5,1 (default: "
                      "--sweep-points from 0 to 1.5 x the case's current)");
  cmd->add_option("--sweep-points", o->sweep_points, "Points of the default current sweep")
      ->check(app::in_domain(Domain::between(2, 1000).whole()));
  cmd->add_option("--width", o->map.width, "Field map width [px] (default 1000)")
      ->check(app::in_domain(Domain::between(300, 10000).whole()));
  cmd->add_option("--height", o->map.height, "Field map height [px] (default 800)")
      ->check(app::in_domain(Domain::between(200, 10000).whole()));
  cmd->add_option("--flux-lines", o->map.flux_lines,
                  "Number of flux lines (contours of r A_phi, or A_z for planar; default 21)")
      ->check(app::in_domain(Domain::between(0, 500).whole()));
  cmd->callback([o] { run(*o); });
});

}  // namespace
