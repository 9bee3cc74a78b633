// rheomag report: a self-contained HTML page of a case's solve (key numbers, inline pictures).

#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "case/case_file.hpp"
#include "figures/picture_solve.hpp"
#include "figures/solve_report.hpp"

namespace {

using namespace rheomag;

struct ReportCommandOptions {
  std::string case_path;
  std::vector<std::string> settings;  // --set KEY=VALUE
  std::string out;
  std::optional<double> current;
  std::vector<double> currents;
  int sweep_points = 11;
};

void run(const ReportCommandOptions& o) {
  const cases::Case c = app::load_case(o.case_path, o.settings);
  const figures::PictureSolve solved =
      figures::solve_for_pictures(c, o.current, o.currents, o.sweep_points);
  const double current =
      o.current ? *o.current : (c.problem.circuits.empty() ? 0.0 : c.problem.circuits[0].current);
  const auto path =
      figures::write_solve_report(o.out, solved.view(), {}, figures::device_sections(c, current));
  std::cout << "wrote " << path.string() << " (open it in a browser)\n";
}

const bool report_registered = app::register_command([](CLI::App& root) {
  auto o = std::make_shared<ReportCommandOptions>();
  CLI::App* cmd = root.add_subcommand(
      "report",
      "Write DIR/report.html: one self-contained page (inline SVG, no other file) with a case's\n"
      "key numbers (gap flux densities, flux linkage, inductances, energy), the pictures of\n"
      "`rheomag plot` and, for a valve with a [valve] flow, its pressure drop against flow at\n"
      "four currents (docs/plots.md).\n"
      "Exit codes: 0 success, 2 bad input, 3 Newton did not converge.");
  cmd->add_option("CASE", o->case_path, "Case file (.toml) or FEMM model (.fem)")->required();
  cmd->add_option("--out", o->out, "Folder to write report.html into (created if absent)")
      ->required()
      ->check(app::non_empty());
  app::add_set_option(cmd, o->settings);
  app::add_quantity(cmd, "--current", o->current, QuantityKind::current,
                    "Current of every circuit (default: the case's currents)");
  app::add_quantities(cmd, "--currents", o->currents, QuantityKind::current,
                      "Currents of the lambda(I), L(I) picture (default: --sweep-points from 0 "
                      "to 1.5 x the case's current)");
  cmd->add_option("--sweep-points", o->sweep_points, "Points of the default current sweep")
      ->check(app::in_domain(Domain::between(2, 1000).whole()));
  cmd->callback([o] { run(*o); });
});

}  // namespace
