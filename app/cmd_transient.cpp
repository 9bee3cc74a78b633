// rheomag transient: step response of a valve's field with eddy currents (current or voltage).

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "app/command.hpp"
#include "case/case_file.hpp"
#include "core/error.hpp"
#include "figures/transient_step.hpp"
#include "plot/figure.hpp"
#include "transient/from_case.hpp"
#include "transient/report.hpp"
#include "transient/vtk_series.hpp"
#include "valve/solved_valve.hpp"

namespace {

using namespace rheomag;

struct TransientCliOptions {
  std::string case_path;
  std::optional<double> current, voltage;
  double from = 0.0;
  double duration = 0.0;
  int steps = 0;
  double tolerance = 1e-4;
  int newton_iterations = 50;
  std::string scheme = "midpoint";
  std::optional<double> resistance;
  std::string vtk_series;
  int vtk_stride = 1;
  std::string plot;  // step-response picture (.png / .svg)
  bool json = false;
  bool quiet = false;
};

/// Coil resistance: --resistance, else [transient] resistance, else from the winding's wire.
std::optional<double> coil_resistance(const TransientCliOptions& o, const cases::Case& c,
                                      const transient::CaseTransient& set_up) {
  if (o.resistance) {
    if (!(*o.resistance > 0.0) || !std::isfinite(*o.resistance))
      throw InputError("--resistance: expected a resistance > 0 Ohm");
    return o.resistance;
  }
  if (set_up.case_options.resistance) return set_up.case_options.resistance;
  return valve::wire_resistance(c, *set_up.statics);
}

void run(const TransientCliOptions& o) {
  if (o.current.has_value() == o.voltage.has_value())
    throw InputError("give exactly one of --current A or --voltage V");
  if (!(o.duration > 0.0) || !std::isfinite(o.duration))
    throw InputError("--duration: expected a time > 0 s");
  if (!std::isfinite(o.from)) throw InputError("--from: expected a finite current in A");
  if (!o.plot.empty() && !plot::is_picture_path(o.plot))
    throw InputError("--plot: expected a file name ending in .png or .svg");
  const cases::Case c = cases::load_case(o.case_path);
  if (c.problem.circuits.empty())
    throw InputError(o.case_path + ": the case has no circuit to drive");
  const transient::CaseTransient set_up = transient::transient_from_case(c);

  transient::TransientOptions options =
      transient::step_options(o.voltage ? transient::Drive::voltage : transient::Drive::current,
                              o.voltage ? *o.voltage : *o.current, o.duration);
  options.from_current = o.from;
  options.steps = o.steps;
  options.tolerance = o.tolerance;
  options.newton.max_iterations = o.newton_iterations;
  options.scheme = transient::kTimeSchemeNames.parse(o.scheme, "--scheme");
  const std::optional<double> resistance = coil_resistance(o, c, set_up);
  if (o.voltage && !resistance)
    throw InputError(o.case_path +
                     ": a voltage step needs the coil resistance: give the wire ([valve] wire = "
                     "\"AWG 24\"), [transient] resistance, or --resistance");
  options.resistance = resistance.value_or(0.0);
  const auto start = std::chrono::steady_clock::now();
  double last_print = 0.0;
  if (!o.quiet) {
    options.progress = [&](const ProgressEvent& e) {
      if (e.elapsed - last_print < 1.0 && e.done < e.total) return;
      last_print = e.elapsed;
      std::cerr << "rheomag transient: " << e.detail << " (" << e.elapsed << " s)\n";
    };
  }
  std::unique_ptr<transient::VtkSeries> series;
  if (!o.vtk_series.empty())
    series = std::make_unique<transient::VtkSeries>(o.vtk_series, *set_up.solver, o.vtk_stride);
  transient::StateCallback on_state;
  if (series) on_state = [&](const transient::TransientState& s) { series->write(s); };
  const transient::TransientResult result = set_up.solver->run(options, on_state);
  if (series) series->finish();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.plot.empty())
    figures::transient_step_figure(result, c.name, 900, 1000).write(o.plot, "--plot");

  if (o.json) {
    nlohmann::json j = transient::transient_json(result, options);
    j["case"] = c.name;
    j["seconds"] = seconds;
    if (series) j["vtk_series"] = o.vtk_series, j["vtk_files"] = series->files();
    if (!o.plot.empty()) j["plot"] = o.plot;
    rheomag::app::print_json(j, 2);
    return;
  }
  std::cout << "case " << c.name << " (" << o.case_path << ")\n"
            << transient::transient_summary(result, options);
  if (series)
    std::cout << "wrote " << o.vtk_series << "/series.pvd and " << series->files()
              << " states (open it in ParaView)\n";
  if (!o.plot.empty()) std::cout << "wrote " << o.plot << " (step response)\n";
}

const bool transient_registered = app::register_command([](CLI::App& root) {
  auto o = std::make_shared<TransientCliOptions>();
  CLI::App* cmd = root.add_subcommand(
      "transient",
      "Step response of the field with eddy currents in the steel (transient magnetics).\n"
      "From the steady state at --from (default 0 A), the first circuit is driven at t = 0 by a\n"
      "current step (--current) or a voltage step through the coil's resistance (--voltage;\n"
      "resistance from the case's wire and winding, [transient] resistance or --resistance).\n"
      "Solves sigma dA/dt + curl(nu(|B|) curl A) = J_s with the circuit equation V = R i +\n"
      "dlambda/dt (docs/transient.md). Prints the flux linkage's t63 and t90, the gaps' mean |B|\n"
      "over time and the energy balance. Conductivities come from the materials; remedies\n"
      "(slots, laminations, SMC) from the case's [transient] table.\n"
      "Exit codes: 0 success, 2 bad input, 3 a time step did not converge (the time is named).");
  cmd->add_option("CASE", o->case_path, "Case file (.toml) or FEMM model (.fem)")->required();
  auto* current = cmd->add_option("--current", o->current, "Current after the step [A]");
  auto* voltage = cmd->add_option("--voltage", o->voltage, "Supply voltage after the step [V]");
  current->excludes(voltage);
  cmd->add_option("--from", o->from, "Current before the step (steady state) [A]");
  cmd->add_option("--duration", o->duration, "Simulated time after the step [s]")->required();
  cmd->add_option("--steps", o->steps, "Equal time steps (default: adaptive steps)")
      ->check(rheomag::app::in_domain(rheomag::Domain::count()));
  cmd->add_option("--tolerance", o->tolerance,
                  "Adaptive steps: local error of the flux linkage per step, relative to its "
                  "change (default 1e-4)")
      ->check(rheomag::app::in_domain(rheomag::Domain::positive()));
  cmd->add_option("--newton-iterations", o->newton_iterations,
                  "Newton iterations per time step before it is repeated smaller (adaptive) or the "
                  "run stops with exit 3 (default 50)")
      ->check(rheomag::app::in_domain(rheomag::Domain::count()));
  cmd->add_option("--scheme", o->scheme, "midpoint (default, 2nd order) or backward_euler")
      ->check(rheomag::app::non_empty());
  cmd->add_option("--resistance", o->resistance, "Coil resistance [Ohm] (overrides the case)");
  cmd->add_option("--vtk-series", o->vtk_series,
                  "Write the states as DIR/state_NNNNN.vtu (fields and the eddy-current density "
                  "J_phi) and DIR/series.pvd (ParaView)")
      ->check(rheomag::app::non_empty());
  cmd->add_option("--vtk-stride", o->vtk_stride,
                  "With --vtk-series: write the first state, every Nth and the last (default 1)")
      ->check(rheomag::app::in_domain(rheomag::Domain::count()));
  cmd->add_option("--plot", o->plot,
                  "Draw I(t), lambda(t) and the gaps' |B|(t) with t63/t90 to this .png or .svg")
      ->check(rheomag::app::output_file_in_writable_folder());
  cmd->add_flag("--json", o->json, "Print one JSON object (SI units) instead of the summary");
  cmd->add_flag("--quiet", o->quiet, "No progress on stderr");
  cmd->callback([o] { run(*o); });
});

}  // namespace
