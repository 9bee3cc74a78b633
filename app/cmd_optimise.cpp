// rheomag optimise CASE: design optimisation of a case's valve with the FE in the loop (Ipopt,
// central- or forward-difference gradients on a morphed fixed-topology mesh). Logic in
// optimise/run.hpp; format of the [optimise] table in docs/optimisation.md.

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/progress_lines.hpp"
#include "case/case_file.hpp"
#include "optimise/run.hpp"

namespace {

struct OptimiseCli {
  std::string case_file;
  std::vector<std::string> settings;  // --set KEY=VALUE: the starting design
  std::string out_dir = ".";
  bool json = false;
  bool verbose = false;
  bool quiet = false;
};

nlohmann::json design_json(const rheomag::optimise::DesignReport& d,
                           const rheomag::optimise::OptimiseSpec& spec) {
  nlohmann::json variables = nlohmann::json::object();
  for (std::size_t i = 0; i < spec.variables.size(); ++i) variables[spec.variables[i].key] = d.x[i];
  nlohmann::json quantities = nlohmann::json::object();
  for (rheomag::design::Quantity q : rheomag::design::all_quantities())
    if (!std::isnan(d.quantities[q]))
      quantities[rheomag::design::quantity_name(q)] = d.quantities[q];
  if (d.response_time_transient) quantities["response_time_transient"] = *d.response_time_transient;
  nlohmann::json constraints = nlohmann::json::array();
  for (const auto& s : d.constraints) {
    nlohmann::json c = {{"quantity", rheomag::design::quantity_name(s.constraint.quantity)},
                        {"value", s.value},
                        {"satisfied", s.satisfied},
                        {"active", s.active}};
    if (std::isfinite(s.constraint.lower)) c["min"] = s.constraint.lower;
    if (std::isfinite(s.constraint.upper)) c["max"] = s.constraint.upper;
    constraints.push_back(c);
  }
  return {{"objective", d.objective},
          {"feasible", d.feasible},
          {"violations", rheomag::optimise::violations_json(d)},
          {"variables", variables},
          {"quantities", quantities},
          {"constraints", constraints},
          {"variables_at_bounds", d.variables_at_bounds},
          {"strict_vertex", d.strict_vertex}};
}

int run_optimise(const OptimiseCli& o) {
  using namespace rheomag;
  const auto c = app::load_case(o.case_file, o.settings);
  optimise::OptimiseOptions options;
  options.out_dir = o.out_dir;
  options.print_level = o.verbose && !o.json ? 5 : 0;
  if (!o.quiet) options.progress = app::progress_lines("optimise", std::cerr);
  const auto r = optimise::run_optimisation(c, options);
  if (o.json) {
    nlohmann::json out = {{"case", c.name},
                          {"objective", r.spec.objective},
                          {"sense", r.spec.maximise ? "maximise" : "minimise"},
                          {"status", r.status},
                          {"converged", r.converged},
                          {"iterations", r.iterations},
                          {"objective_change", optimise::objective_change_text(r)},
                          {"initial", design_json(r.initial, r.spec)},
                          {"optimal", design_json(r.optimal, r.spec)},
                          {"conflicts", r.conflicts},
                          {"case_file", r.case_file.string()},
                          {"history_file", r.history_file.string()},
                          {"vtu_file", r.vtu_file.string()},
                          {"fe_solves", r.fe_solves},
                          {"meshes", r.meshes},
                          {"seconds", r.seconds}};
    if (r.response_check)
      out["response_check"] = {{"reduced", r.response_check->reduced},
                               {"transient", r.response_check->transient},
                               {"correction", r.response_check->correction},
                               {"rounds", r.response_check->rounds}};
    if (r.combinations.size() > 1 || !r.spec.choices.empty()) {
      nlohmann::json combinations = nlohmann::json::array();
      for (std::size_t k = 0; k < r.combinations.size(); ++k) {
        const auto& m = r.combinations[k];
        nlohmann::json choice = nlohmann::json::object();
        for (const auto& [key, value] : m.choice) choice[key] = value;
        combinations.push_back({{"choice", choice},
                                {"chosen", k == r.chosen},
                                {"status", m.status},
                                {"fe_solves", m.fe_solves},
                                {"optimal", design_json(m.optimal, r.spec)}});
      }
      out["combinations"] = combinations;
    }
    if (r.pareto) {
      nlohmann::json points = nlohmann::json::array();
      for (const auto& p : r.pareto->points)
        points.push_back({{"epsilon", p.epsilon},
                          {"fe_solves", p.fe_solves},
                          {"design", design_json(p.design, r.spec)}});
      nlohmann::json files = nlohmann::json::array();
      for (const auto& f : r.pareto_files) files.push_back(f.string());
      out["pareto"] = {{"quantity", rheomag::design::quantity_name(r.pareto->pareto.quantity)},
                       {"sense", r.pareto->pareto.maximise ? "maximise" : "minimise"},
                       {"points", points},
                       {"second_alone", design_json(r.pareto->second_alone, r.spec)},
                       {"files", files}};
    }
    rheomag::app::print_json(out, 2);
  } else {
    std::cout << optimise::format_summary(r);
  }
  return r.optimal.feasible ? 0 : 1;
}

const bool optimise_registered = rheomag::app::register_command([](CLI::App& root) {
  auto o = std::make_shared<OptimiseCli>();
  CLI::App* cmd = root.add_subcommand(
      "optimise",
      "Design optimisation of a case's MR valve with the FE in the loop. The case's [optimise]\n"
      "table names the design variables (any numeric case key, e.g. geometry.neck_radius, with\n"
      "bounds in the file's units), the objective (dp_on, dp_off, dynamic_range, power,\n"
      "time_constant, rise_time, ..., or a weighted sum; maximise or minimise), constraints on\n"
      "those quantities (SI units), the current and the flow; optionally discrete choices\n"
      "(enumerate: steel, fluid) and an epsilon-constraint Pareto front ([optimise.pareto]).\n"
      "Ipopt (interior point, L-BFGS) with central (or forward: differences = \"forward\")\n"
      "difference gradients on a morphed mesh of\n"
      "fixed topology. Writes CASE_optimal.toml (solvable by 'rheomag solve'),\n"
      "CASE_history.csv, CASE_optimal.vtu (and pareto.csv, pareto.png); prints initial vs\n"
      "optimal.\n"
      "Exit 1 if no feasible design was found (the conflicting constraints are listed).\n"
      "See docs/optimisation.md.");
  cmd->add_option("case", o->case_file, "Case file (.toml) with an [optimise] table")
      ->required()
      ->check(CLI::ExistingFile);
  rheomag::app::add_set_option(cmd, o->settings);
  cmd->add_option("--out", o->out_dir, "Output directory (default: current directory)")
      ->check(rheomag::app::non_empty());
  cmd->add_flag("--json", o->json, "Print one JSON object to stdout");
  cmd->add_flag("--verbose", o->verbose, "Show Ipopt's iteration log");
  cmd->add_flag("--quiet", o->quiet, "No progress lines on stderr");
  cmd->callback([o] {
    const int code = run_optimise(*o);
    if (code != 0) {  // infeasible: the report is printed; exit 1 (not an input error)
      std::cout.flush();
      std::exit(code);
    }
  });
});

}  // namespace
