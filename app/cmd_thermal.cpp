// rheomag thermal CASE: the coil's and the fluid's temperatures of a device case at one
// operating point (steady, coupled or at a given temperature, or heating from ambient), the heat
// leaving through each surface. Logic in thermal/thermal_report.hpp.

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/command.hpp"
#include "case/case_file.hpp"
#include "core/error.hpp"
#include "plot/figure.hpp"
#include "thermal/thermal_pictures.hpp"
#include "thermal/thermal_report.hpp"

namespace {

struct ThermalCli {
  std::string case_file;
  std::vector<std::string> settings;
  std::optional<double> current, flow, velocity, speed, duration;
  std::optional<double> temperature, ambient, convection, limit;
  double duty = 1.0;
  int steps = 200;
  std::string vtk, plot, plot_history;
  bool json = false;
};

void run(const ThermalCli& o) {
  using namespace rheomag;
  const int motions = o.flow.has_value() + o.velocity.has_value() + o.speed.has_value();
  if (motions > 1)
    throw InputError(
        "--flow, --velocity and --speed: give at most one (a valve's flow, a "
        "damper's piston velocity or a brake's rotor speed)");
  for (const auto& [option, file] :
       {std::pair{"--plot", &o.plot}, {"--plot-history", &o.plot_history}})
    if (!file->empty() && !plot::is_picture_path(*file))
      throw InputError(std::string(option) + ": expected a file name ending in .png or .svg");
  if (!o.plot_history.empty() && !o.duration)
    throw InputError("--plot-history: draws a transient's heating; give --duration too");
  const cases::Case c = app::load_case(o.case_file, o.settings);
  thermal::ThermalRequest request;
  request.point.duty = o.duty;
  if (o.current) {
    request.point.current = *o.current;
  } else {
    for (const auto& circuit : c.problem.circuits) request.point.current = circuit.current;
  }
  if (o.flow) request.point = {thermal::Motion::flow, request.point.current, *o.flow, o.duty};
  if (o.velocity)
    request.point = {thermal::Motion::velocity, request.point.current, *o.velocity, o.duty};
  if (o.speed) request.point = {thermal::Motion::speed, request.point.current, *o.speed, o.duty};
  request.temperature = o.temperature;
  request.duration = o.duration;
  request.steps = o.steps;
  request.ambient = o.ambient;
  request.convection = o.convection;
  request.limit = o.limit;
  const thermal::ThermalReport report = thermal::run_thermal(c, request);
  if (!o.vtk.empty()) thermal::write_thermal_vtu(report, o.vtk);
  if (!o.plot.empty()) thermal::draw_temperature_map(report).figure.write(o.plot, "--plot");
  if (!o.plot_history.empty())
    thermal::draw_heating_curves(report).write(o.plot_history, "--plot-history");
  if (o.json) {
    nlohmann::json j = thermal::thermal_json(report);
    if (!o.settings.empty()) j["set"] = o.settings;
    if (!o.vtk.empty()) j["vtk"] = o.vtk;
    if (!o.plot.empty()) j["plot"] = o.plot;
    if (!o.plot_history.empty()) j["plot_history"] = o.plot_history;
    app::print_json(j, 2);
  } else {
    std::cout << thermal::thermal_text(report);
    if (!o.vtk.empty()) std::cout << "wrote " << o.vtk << " (temperature, heat source)\n";
    if (!o.plot.empty()) std::cout << "wrote " << o.plot << " (temperature map)\n";
    if (!o.plot_history.empty()) std::cout << "wrote " << o.plot_history << " (heating curves)\n";
  }
}

const bool thermal_registered = rheomag::app::register_command([](CLI::App& root) {
  using rheomag::Domain;
  using rheomag::QuantityKind;
  auto o = std::make_shared<ThermalCli>();
  CLI::App* cmd = root.add_subcommand(
      "thermal",
      "Temperatures of a device case at one operating point: heat conduction on the field's\n"
      "mesh with the coil's I^2 R(T) and the fluid's dissipation (valve dp Q with --flow, damper\n"
      "F v with --velocity, brake T w with --speed) as sources, convection to the ambient on\n"
      "the outer surfaces ([thermal] in the case: ambient, convection, surfaces, limit). By\n"
      "default the steady state where the fluid's viscosity and yield stress and the coil's\n"
      "resistance match their own temperatures (a fixed point); --temperature runs the chain\n"
      "at a given temperature; --duration heats the device from ambient. See docs/thermal.md.");
  cmd->add_option("case", o->case_file, "Case file (.toml or .fem)")
      ->required()
      ->check(CLI::ExistingFile);
  rheomag::app::add_set_option(cmd, o->settings);
  rheomag::app::add_quantity(cmd, "--current", o->current, QuantityKind::current,
                             "Coil current (default: the case's circuit current)");
  auto* flow = rheomag::app::add_quantity(cmd, "--flow", o->flow, QuantityKind::flow,
                                          "Valve: flow through the gaps");
  auto* velocity =
      rheomag::app::add_quantity(cmd, "--velocity", o->velocity, QuantityKind::velocity,
                                 "Damper: piston velocity ([damper] in the case)");
  auto* speed = rheomag::app::add_quantity(cmd, "--speed", o->speed, QuantityKind::angular_speed,
                                           "Brake: rotor speed");
  flow->excludes(velocity)->excludes(speed);
  velocity->excludes(speed);
  cmd->add_option("--duty", o->duty,
                  "Fraction of the time at this operating point, in [0, 1]; the rest the coil "
                  "is off and the fluid still (the sources are averaged over the cycle)")
      ->check(rheomag::app::in_domain(Domain::between(0.0, 1.0)))
      ->default_val(1.0);
  rheomag::app::add_quantity(cmd, "--duration", o->duration, QuantityKind::time,
                             "Heat the device from ambient for this long (a transient) "
                             "instead of the steady state");
  cmd->add_option("--steps", o->steps, "Time steps of the transient (BDF2)")
      ->check(rheomag::app::in_domain(Domain::count()))
      ->default_val(200);
  cmd->add_option("--temperature", o->temperature,
                  "Run the chain (fluid and coil) at this temperature in deg C instead of "
                  "its own steady temperature")
      ->check(rheomag::app::in_domain(Domain::between(-200.0, 250.0, "deg C")));
  cmd->add_option("--ambient", o->ambient,
                  "Ambient temperature in deg C (default: [thermal] "
                  "ambient, else 20)")
      ->check(rheomag::app::in_domain(Domain::between(-273.15, 2000.0, "deg C")));
  cmd->add_option("--convection", o->convection,
                  "Convection coefficient h on the outer surfaces in W/(m^2 K) (default: "
                  "[thermal] convection, else 10)")
      ->check(rheomag::app::in_domain(Domain::non_negative("W/(m^2 K)")));
  cmd->add_option("--limit", o->limit,
                  "Largest allowed temperature in deg C: the report says whether the steady "
                  "state stays under it, or when the transient reaches it")
      ->check(rheomag::app::in_domain(Domain::between(-273.15, 2000.0, "deg C")));
  cmd->add_option("--vtk", o->vtk,
                  "Write the temperature (deg C) and heat source (W/m^3) to this .vtu file")
      ->check(rheomag::app::output_file_in_writable_folder());
  cmd->add_option("--plot", o->plot,
                  "Draw the temperature map (banded colours, isotherms, region outlines; the "
                  "steady state or the transient's last) to this .png or .svg file")
      ->check(rheomag::app::output_file_in_writable_folder());
  cmd->add_option("--plot-history", o->plot_history,
                  "With --duration: draw the coil's and the fluid's mean and hottest "
                  "temperatures against time, with the limit, to this .png or .svg file")
      ->check(rheomag::app::output_file_in_writable_folder());
  cmd->add_flag("--json", o->json, "Print one JSON object to stdout");
  cmd->callback([o] { run(*o); });
});

}  // namespace
