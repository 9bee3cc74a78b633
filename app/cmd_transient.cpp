// rheomag transient: step response of a valve's field with eddy currents (current or voltage).

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "app/command.hpp"
#include "case/case_file.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "magnetostatics/report.hpp"
#include "magnetostatics/results.hpp"
#include "transient/case_options.hpp"
#include "transient/report.hpp"
#include "transient/transient_solver.hpp"
#include "valve/coil.hpp"
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
  bool json = false;
  bool quiet = false;
};

/// Coil resistance: --resistance, else [transient] resistance, else from the winding's wire.
std::optional<double> coil_resistance(const TransientCliOptions& o, const cases::Case& c,
                                      const transient::TransientCaseOptions& t,
                                      const magnetostatics::MagnetostaticSolver& statics) {
  if (o.resistance) {
    if (!(*o.resistance > 0.0) || !std::isfinite(*o.resistance))
      throw InputError("--resistance: expected a resistance > 0 Ohm");
    return o.resistance;
  }
  if (t.resistance) return t.resistance;
  const valve::ValveOptions valve_options = valve::read_valve_options(c);
  if (valve_options.wire.empty()) return std::nullopt;
  const valve::CoilSpec spec = valve::coil_spec(statics, valve_options);
  return valve::coil_properties(spec, 0.0, 0.0).resistance;
}

/// Writes every state as DIR/state_NNNNN.vtu plus DIR/series.pvd (ParaView's time series).
class VtkSeries {
 public:
  VtkSeries(std::filesystem::path dir, const magnetostatics::MagnetostaticSolver& statics)
      : dir_(std::move(dir)), statics_(statics) {
    std::error_code error;
    std::filesystem::create_directories(dir_, error);
    if (error) throw InputError("--vtk-series: cannot create " + dir_.string());
  }
  void write(const transient::TransientState& s) {
    char name[32];
    std::snprintf(name, sizeof name, "state_%05d.vtu", count_++);
    magnetostatics::Solution solution;
    solution.currents.assign(statics_.problem().circuits.size(), 0.0);
    for (std::size_t c = 0; c < solution.currents.size(); ++c)
      solution.currents[c] = statics_.problem().circuits[c].current;
    solution.currents[0] = s.current;
    solution.a = s.a;
    for (int c = 0; c < static_cast<int>(solution.currents.size()); ++c)
      solution.flux_linkage.push_back(statics_.circuit_source(c).dot(s.a));
    const auto results = magnetostatics::compute_results(statics_, solution);
    magnetostatics::write_results_vtu((dir_ / name).string(), statics_, solution, results);
    collection_ << "    <DataSet timestep=\"" << s.time << "\" part=\"0\" file=\"" << name
                << "\"/>\n";
  }
  void finish() {
    write_file_atomically(dir_ / "series.pvd",
                          "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
                          "version=\"0.1\">\n  <Collection>\n" +
                              collection_.str() + "  </Collection>\n</VTKFile>\n");
  }

 private:
  std::filesystem::path dir_;
  const magnetostatics::MagnetostaticSolver& statics_;
  std::ostringstream collection_;
  int count_ = 0;
};

void run(const TransientCliOptions& o) {
  if (o.current.has_value() == o.voltage.has_value())
    throw InputError("give exactly one of --current A or --voltage V");
  if (!(o.duration > 0.0) || !std::isfinite(o.duration))
    throw InputError("--duration: expected a time > 0 s");
  if (!std::isfinite(o.from)) throw InputError("--from: expected a finite current in A");
  const cases::Case c = cases::load_case(o.case_path);
  if (c.problem.circuits.empty())
    throw InputError(o.case_path + ": the case has no circuit to drive");
  const transient::TransientCaseOptions case_options = transient::read_transient_case(c);
  auto statics = magnetostatics::make_solver(c.problem);
  transient::TransientSolver solver(
      *statics, transient::eddy_coefficients(statics->problem(), case_options.remedies));

  transient::TransientOptions options;
  options.drive = o.voltage ? transient::Drive::voltage : transient::Drive::current;
  options.value = o.voltage ? *o.voltage : *o.current;
  options.from_current = o.from;
  options.duration = o.duration;
  options.steps = o.steps;
  options.tolerance = o.tolerance;
  options.newton.max_iterations = o.newton_iterations;
  options.scheme = transient::kTimeSchemeNames.parse(o.scheme, "--scheme");
  const std::optional<double> resistance = coil_resistance(o, c, case_options, *statics);
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
  std::unique_ptr<VtkSeries> series;
  if (!o.vtk_series.empty()) series = std::make_unique<VtkSeries>(o.vtk_series, *statics);
  transient::StateCallback on_state;
  if (series) on_state = [&](const transient::TransientState& s) { series->write(s); };
  const transient::TransientResult result = solver.run(options, on_state);
  if (series) series->finish();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (o.json) {
    nlohmann::json j = transient::transient_json(result, options);
    j["case"] = c.name;
    j["seconds"] = seconds;
    if (series) j["vtk_series"] = o.vtk_series;
    rheomag::app::print_json(j, 2);
    return;
  }
  std::cout << "case " << c.name << " (" << o.case_path << ")\n"
            << transient::transient_summary(result, options);
  if (series) std::cout << "wrote " << o.vtk_series << "/series.pvd (open it in ParaView)\n";
}

const bool registered = app::register_command([](CLI::App& root) {
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
      ->check(CLI::PositiveNumber);
  cmd->add_option("--tolerance", o->tolerance,
                  "Adaptive steps: local error of the flux linkage per step, relative to its "
                  "change (default 1e-4)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--newton-iterations", o->newton_iterations,
                  "Newton iterations per time step before it is repeated smaller (adaptive) or the "
                  "run stops with exit 3 (default 50)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--scheme", o->scheme, "midpoint (default, 2nd order) or backward_euler")
      ->check(rheomag::app::non_empty());
  cmd->add_option("--resistance", o->resistance, "Coil resistance [Ohm] (overrides the case)");
  cmd->add_option("--vtk-series", o->vtk_series,
                  "Write every state as DIR/state_NNNNN.vtu and DIR/series.pvd (ParaView)")
      ->check(rheomag::app::non_empty());
  cmd->add_flag("--json", o->json, "Print one JSON object (SI units) instead of the summary");
  cmd->add_flag("--quiet", o->quiet, "No progress on stderr");
  cmd->callback([o] { run(*o); });
});

}  // namespace
