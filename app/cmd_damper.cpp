// rheomag damper CASE: force-velocity curves of a flow-mode damper piston case at a list of coil
// currents (FE field -> mixed-mode gaps -> force). Logic in valve/damper_report.hpp.

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/progress_lines.hpp"
#include "case/case_file.hpp"
#include "core/error.hpp"
#include "figures/device_curves.hpp"
#include "plot/figure.hpp"
#include "valve/damper_report.hpp"

namespace {

struct DamperCli {
  std::string case_file;
  std::vector<std::string> settings;  // --set KEY=VALUE
  std::vector<double> currents, velocities;
  std::string plot;  // curves picture (.png / .svg)
  bool json = false;
};

void run_damper(const DamperCli& o) {
  using namespace rheomag;
  if (!o.plot.empty() && !plot::is_picture_path(o.plot))
    throw InputError("--plot: expected a file name ending in .png or .svg");
  const cases::Case c = app::load_case(o.case_file, o.settings);
  const auto report = valve::evaluate_damper(c, o.currents, o.velocities,
                                             app::progress_lines("damper", std::cerr, 2.0, 2.0));
  if (!o.plot.empty()) figures::damper_curves_figure(report, 900, 600).write(o.plot, "--plot");
  if (o.json) {
    nlohmann::json j = valve::damper_json(report);
    if (!o.settings.empty()) j["set"] = o.settings;
    if (!o.plot.empty()) j["plot"] = o.plot;
    app::print_json(j, 2);
  } else {
    if (!o.settings.empty()) std::cout << c.description << "\n";  // the --set edits
    std::cout << valve::damper_text(report);
    if (!o.plot.empty()) std::cout << "wrote " << o.plot << " (force-velocity)\n";
  }
}

const bool damper_registered = rheomag::app::register_command([](CLI::App& root) {
  auto o = std::make_shared<DamperCli>();
  CLI::App* cmd = root.add_subcommand(
      "damper",
      "Force-velocity curves of a flow-mode MR damper piston case: the FE field at each\n"
      "current, the exact mixed-mode (pressure + moving wall) Bingham / Herschel-Bulkley law\n"
      "integrated along every annular gap of the piston with the local tau_y(B(z)), then the\n"
      "force F = dp A_piston + wall shear + gas pressure x rod area. Velocity > 0 compresses\n"
      "(either sign). SI units. The case needs a [damper] table. See docs/dampers.md.");
  cmd->add_option("case", o->case_file, "Case file (.toml)")->required()->check(CLI::ExistingFile);
  rheomag::app::add_set_option(cmd, o->settings);
  rheomag::app::add_quantities(cmd, "--current", o->currents, rheomag::QuantityKind::current,
                               "Coil currents, comma-separated (default: the case's circuit "
                               "current)");
  rheomag::app::add_quantities(cmd, "--velocity", o->velocities, rheomag::QuantityKind::velocity,
                               "Piston velocities, comma-separated (default: [damper] velocity)");
  cmd->add_option("--plot", o->plot,
                  "Draw force against velocity, one curve per current, to this .png or .svg")
      ->check(rheomag::app::output_file_in_writable_folder());
  cmd->add_flag("--json", o->json, "Print one JSON object to stdout");
  cmd->callback([o] { run_damper(*o); });
});

}  // namespace
