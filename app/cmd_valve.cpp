// rheomag valve CASE: steady-state pressure drop of a case's valve (its magnetised gaps, listed
// passages and minor losses in series, field from the FE solve) at a list of currents and flow
// rates, plus the coil. Logic in valve/valve_report.hpp.

#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/progress_lines.hpp"
#include "case/case_file.hpp"
#include "core/error.hpp"
#include "figures/valve_curves.hpp"
#include "plot/figure.hpp"
#include "valve/coil.hpp"
#include "valve/valve_report.hpp"

namespace {

struct ValveCli {
  std::string case_file;
  std::vector<std::string> settings;  // --set KEY=VALUE
  std::vector<double> currents, flows;
  std::string wire;
  std::string plot;  // dp-Q picture (.png / .svg)
  double temperature = NAN;
  bool json = false;
};

void run_valve(const ValveCli& o) {
  using namespace rheomag;
  if (!o.plot.empty() && !plot::is_picture_path(o.plot))
    throw InputError("--plot: expected a file name ending in .png or .svg");
  const auto c = app::load_case(o.case_file, o.settings);
  valve::ValveOptions options = valve::read_valve_options(c);
  if (!o.wire.empty()) {
    try {
      options.wire_diameter = cases::wire_diameter(o.wire);
    } catch (const InputError& e) {
      throw InputError(std::string("--wire: ") + e.what());
    }
    options.wire = o.wire;
  }
  if (!std::isnan(o.temperature)) {
    const std::string why = valve::kCoilTemperature.violation(o.temperature);
    if (!why.empty())
      throw InputError("--temperature: " + why + " (where the linear resistivity of copper holds)");
    options.temperature = o.temperature;
  }
  const valve::ValveReport report = valve::evaluate_valve(
      c, options, o.currents, o.flows, app::progress_lines("valve", std::cerr, 2.0, 2.0));
  if (!o.plot.empty()) figures::valve_curves_figure(report, 900, 800).write(o.plot, "--plot");
  if (o.json) {
    nlohmann::json j = valve::valve_json(report);
    if (!o.settings.empty()) j["set"] = o.settings;
    if (!o.plot.empty()) j["plot"] = o.plot;
    app::print_json(j, 2);
  } else {
    if (!o.settings.empty()) std::cout << c.description << "\n";  // the --set edits
    std::cout << valve::valve_text(report);
    if (!o.plot.empty()) std::cout << "wrote " << o.plot << " (dp-Q, dynamic range)\n";
  }
}

const bool valve_registered = rheomag::app::register_command([](CLI::App& root) {
  auto o = std::make_shared<ValveCli>();
  CLI::App* cmd = root.add_subcommand(
      "valve",
      "Steady-state pressure drop of a case's MR valve: the FE field at each current, the\n"
      "exact Bingham law integrated along every magnetised gap (in series) with the local\n"
      "tau_y(B(s)), for each flow rate; also the one-average-B shortcut and the coil (turns,\n"
      "R at temperature, L from the FE, L/R, I^2 R). SI units. Unmagnetised passages and minor\n"
      "losses count when the case lists them ([[valve.passage]], [[valve.loss]]). See\n"
      "docs/fluid.md.");
  cmd->add_option("case", o->case_file, "Case file (.toml)")->required()->check(CLI::ExistingFile);
  rheomag::app::add_set_option(cmd, o->settings);
  rheomag::app::add_quantities(cmd, "--current", o->currents, rheomag::QuantityKind::current,
                               "Coil currents, comma-separated (default: the case's circuit "
                               "current)");
  rheomag::app::add_quantities(cmd, "--flow", o->flows, rheomag::QuantityKind::flow,
                               "Flow rates, comma-separated (default: [valve] flow), e.g. "
                               "--flow 1.5L/min,3L/min");
  cmd->add_option("--wire", o->wire, "Wire, e.g. \"AWG 24\" or \"0.5 mm\" (default: [valve] wire)")
      ->check(rheomag::app::non_empty());
  cmd->add_option("--temperature", o->temperature,
                  "Coil temperature [C], -200 to 250 (default 20)");
  cmd->add_option("--plot", o->plot,
                  "Draw dp against Q at each current and the dynamic range to this .png or .svg "
                  "(give several --flow and --current values for curves)")
      ->check(rheomag::app::output_file_in_writable_folder());
  cmd->add_flag("--json", o->json, "Print one JSON object to stdout");
  cmd->callback([o] { run_valve(*o); });
});

}  // namespace
