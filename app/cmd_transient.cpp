// rheomag transient: step response of a valve's field with eddy currents (current or voltage).

#include <chrono>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "case/case_file.hpp"
#include "core/error.hpp"
#include "core/format_text.hpp"
#include "coupling/quasi_static_request.hpp"
#include "coupling/step_request.hpp"
#include "figures/transient_step.hpp"
#include "plot/figure.hpp"
#include "transient/from_case.hpp"
#include "transient/quasi_static.hpp"
#include "transient/quasi_static_report.hpp"
#include "transient/report.hpp"
#include "transient/vtk_series.hpp"

namespace {

using namespace rheomag;

struct TransientCliOptions {
  std::string case_path;
  std::vector<std::string> settings;  // --set KEY=VALUE
  coupling::StepRequest request;
  std::string vtk_series;
  int vtk_stride = 1;
  std::string plot;  // step-response picture (.png / .svg)
  bool json = false;
  bool quiet = false;
  bool quasi_static = false;                     // the reduction instead of time stepping
  const CLI::Option* duration_option = nullptr;  // --duration (given or not)
  int table_points = 8;                          // its starting currents
};

/// `--quasi-static`: the step's rise times from static solves alone (transient/quasi_static.hpp).
void run_quasi_static(const TransientCliOptions& o, const cases::Case& c) {
  const transient::QuasiStaticRun run =
      coupling::quasi_static_response(c, o.case_path, o.request, o.table_points);
  if (o.json) {
    nlohmann::json j = transient::quasi_static_json(run);
    j["case"] = c.name;
    if (!o.settings.empty()) j["set"] = o.settings;
    rheomag::app::print_json(j, 2);
    return;
  }
  std::cout << "case " << c.name << " (" << o.case_path << ")\n";
  if (!o.settings.empty()) std::cout << c.description << "\n";
  std::cout << transient::quasi_static_summary(run);
}

void run(const TransientCliOptions& o) {
  if (!o.plot.empty() && !plot::is_picture_path(o.plot))
    throw InputError("--plot: expected a file name ending in .png or .svg");
  const cases::Case c = app::load_case(o.case_path, o.settings);
  if (o.quasi_static) {
    if (!o.vtk_series.empty() || !o.plot.empty())
      throw InputError("--quasi-static: no states to write; drop --vtk-series and --plot");
    run_quasi_static(o, c);
    return;
  }
  if (o.duration_option->count() == 0)
    throw InputError("--duration is required (the simulated time after the step), e.g. 50ms");
  coupling::check_step_request(o.request);
  coupling::StepRequest request = o.request;
  double last_print = 0.0;
  if (!o.quiet) {
    request.progress = [&](const ProgressEvent& e) {
      if (e.elapsed - last_print < 1.0 && e.done < e.total) return;
      last_print = e.elapsed;
      std::cerr << "rheomag transient: " << e.detail << " (" << e.elapsed << " s)\n";
    };
  }
  const coupling::PreparedStep step = coupling::prepare_step(c, o.case_path, request);
  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<transient::VtkSeries> series;
  if (!o.vtk_series.empty())
    series =
        std::make_unique<transient::VtkSeries>(o.vtk_series, *step.set_up.solver, o.vtk_stride);
  transient::StateCallback on_state;
  if (series) on_state = [&](const transient::TransientState& s) { series->write(s); };
  const transient::TransientResult result = step.set_up.solver->run(step.options, on_state);
  if (series) series->finish();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.plot.empty())
    figures::transient_step_figure(result, c.name, 900, 1000).write(o.plot, "--plot");

  if (o.json) {
    nlohmann::json j = transient::transient_json(result, step.options);
    j["case"] = c.name;
    if (!o.settings.empty()) j["set"] = o.settings;
    j["seconds"] = seconds;
    if (series) j["vtk_series"] = o.vtk_series, j["vtk_files"] = series->files();
    if (!o.plot.empty()) j["plot"] = o.plot;
    rheomag::app::print_json(j, 2);
    return;
  }
  std::cout << "case " << c.name << " (" << o.case_path << ")\n";
  if (!o.settings.empty()) std::cout << c.description << "\n";  // the --set edits
  std::cout << transient::transient_summary(result, step.options);
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
  app::add_set_option(cmd, o->settings);
  auto* current = app::add_quantity(cmd, "--current", o->request.current, QuantityKind::current,
                                    "Current after the step");
  auto* voltage = app::add_quantity(cmd, "--voltage", o->request.voltage, QuantityKind::voltage,
                                    "Supply voltage after the step");
  current->excludes(voltage);
  app::add_quantity(cmd, "--from", o->request.from, QuantityKind::current,
                    "Current before the step (steady state; default 0)");
  o->duration_option = app::add_quantity(
      cmd, "--duration", o->request.duration, QuantityKind::time,
      "Simulated time after the step, e.g. 50ms (required unless --quasi-static)");
  cmd->add_option("--steps", o->request.steps, "Equal time steps (default: adaptive steps)")
      ->check(rheomag::app::in_domain(rheomag::Domain::count()));
  cmd->add_option("--tolerance", o->request.tolerance,
                  "Adaptive steps: local error of the flux linkage per step, relative to its "
                  "change (default 1e-4)")
      ->check(rheomag::app::in_domain(rheomag::Domain::positive()));
  cmd->add_option("--newton-iterations", o->request.newton_iterations,
                  "Newton iterations per time step before it is repeated smaller (adaptive) or the "
                  "run stops with exit 3 (default 50)")
      ->check(rheomag::app::in_domain(rheomag::Domain::count()));
  cmd->add_option("--scheme", o->request.scheme, "midpoint (default, 2nd order) or backward_euler")
      ->check(rheomag::app::non_empty());
  cmd->add_option("--resistance", o->request.resistance,
                  "Coil resistance [Ohm] (overrides the case)");
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
  cmd->add_flag("--quasi-static", o->quasi_static,
                "No time stepping: the field stays a static solution of a magnetising current and "
                "the eddy currents load the coil (a one-mode reduction; fast, exact without skin "
                "effect, its error measured in docs/transient.md)");
  cmd->add_option(
         "--table-points", o->table_points,
         format_text("With --quasi-static: equally spaced static solves from 0 to the largest "
                     "current; then each interval's midpoint is solved, and where the table "
                     "before it missed the inductance, the eddy-current load, the flux linkage "
                     "or a gap's |B| there by more than %g %% its two halves are checked in turn "
                     "(default 8: at least 15 solves)",
                     100.0 * transient::kQuasiStaticTableTolerance))
      ->check(rheomag::app::in_domain(rheomag::Domain::between(4.0, 10000.0).whole()));
  cmd->add_flag("--json", o->json, "Print one JSON object (SI units) instead of the summary");
  cmd->add_flag("--quiet", o->quiet, "No progress on stderr");
  cmd->callback([o] { run(*o); });
});

}  // namespace
