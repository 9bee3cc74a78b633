// rheomag brake CASE: torque-speed curves of a shear-mode brake or rotary damper case at a list
// of coil currents (FE field -> drum and disc gaps -> torque). Logic in valve/brake_report.hpp.

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
#include "valve/brake_report.hpp"

namespace {

struct BrakeCli {
  std::string case_file;
  std::vector<std::string> settings;  // --set KEY=VALUE
  std::vector<double> currents, speeds;
  std::string plot;  // curves picture (.png / .svg)
  bool json = false;
};

void run_brake(const BrakeCli& o) {
  using namespace rheomag;
  if (!o.plot.empty() && !plot::is_picture_path(o.plot))
    throw InputError("--plot: expected a file name ending in .png or .svg");
  const cases::Case c = app::load_case(o.case_file, o.settings);
  const auto report = valve::evaluate_brake(c, o.currents, o.speeds,
                                            app::progress_lines("brake", std::cerr, 2.0, 2.0));
  if (!o.plot.empty()) figures::brake_curves_figure(report, 900, 600).write(o.plot, "--plot");
  if (o.json) {
    nlohmann::json j = valve::brake_json(report);
    if (!o.settings.empty()) j["set"] = o.settings;
    if (!o.plot.empty()) j["plot"] = o.plot;
    app::print_json(j, 2);
  } else {
    if (!o.settings.empty()) std::cout << c.description << "\n";  // the --set edits
    std::cout << valve::brake_text(report);
    if (!o.plot.empty()) std::cout << "wrote " << o.plot << " (torque-speed)\n";
  }
}

const bool brake_registered = rheomag::app::register_command([](CLI::App& root) {
  auto o = std::make_shared<BrakeCli>();
  CLI::App* cmd = root.add_subcommand(
      "brake",
      "Torque-speed curves of a shear-mode MR brake or rotary damper case: the FE field at\n"
      "each current; every annular gap region is a drum (inner wall turning, exact Couette\n"
      "flow with partial yielding), every radial gap region one sheared disc face, each with\n"
      "the local tau_y(B). Speed in rad/s (either sign; 0 gives the breakaway torque). SI\n"
      "units. See docs/dampers.md.");
  cmd->add_option("case", o->case_file, "Case file (.toml)")->required()->check(CLI::ExistingFile);
  rheomag::app::add_set_option(cmd, o->settings);
  rheomag::app::add_quantities(cmd, "--current", o->currents, rheomag::QuantityKind::current,
                               "Coil currents, comma-separated (default: the case's circuit "
                               "current)");
  rheomag::app::add_quantities(cmd, "--speed", o->speeds, rheomag::QuantityKind::angular_speed,
                               "Rotor speeds, comma-separated (default: [brake] speed)");
  cmd->add_option("--plot", o->plot,
                  "Draw torque against speed, one curve per current, to this .png or .svg")
      ->check(rheomag::app::output_file_in_writable_folder());
  cmd->add_flag("--json", o->json, "Print one JSON object to stdout");
  cmd->callback([o] { run_brake(*o); });
});

}  // namespace
