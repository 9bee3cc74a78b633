// rheomag damper CASE: force-velocity curves of a flow-mode damper piston case at a list of coil
// currents (FE field -> mixed-mode gaps -> force). Logic in valve/damper.hpp.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "case/case_file.hpp"
#include "core/error.hpp"
#include "valve/damper.hpp"

namespace {

struct DamperCli {
  std::string case_file;
  std::vector<double> currents, velocities;
  bool json = false;
};

void run_damper(const DamperCli& o) {
  using namespace rheomag;
  const auto c = cases::load_case(o.case_file);
  const valve::DamperOptions options = valve::read_damper_options(c);
  std::vector<double> currents = o.currents;
  if (currents.empty())
    for (const auto& circuit : c.problem.circuits) currents = {circuit.current};
  const std::vector<double> velocities = o.velocities.empty() ? options.velocities : o.velocities;
  if (velocities.empty())
    throw InputError(o.case_file +
                     ": no velocity: pass --velocity V[,V...] (m/s) or set "
                     "[damper] velocity in the case");
  valve::DamperChain chain(c, options);
  const auto points = chain.evaluate(currents, velocities);
  const auto [gas_extended, gas_compressed] = valve::gas_force_range(options);
  if (o.json) {
    nlohmann::json out;
    out["case"] = c.name;
    out["fluid"] = chain.fluid().name;
    out["gap_wall"] = std::string(valve::kGapWallNames.name(options.gap_wall));
    out["gas_force_range"] = {gas_extended, gas_compressed};
    out["points"] = nlohmann::json::array();
    for (const auto& p : points) {
      nlohmann::json gaps = nlohmann::json::array();
      for (const auto& g : p.gaps)
        gaps.push_back({{"name", g.name},
                        {"b_average", g.drop.b_average},
                        {"dp", g.drop.dp},
                        {"dp_yield", g.drop.dp_yield},
                        {"dp_viscous", g.drop.dp_viscous},
                        {"wall_force", g.drop.wall_force},
                        {"regime", std::string(fluid::kMixedRegimeNames.name(g.drop.regime))},
                        {"plug_fraction", g.drop.plug_fraction}});
      out["points"].push_back({{"current", p.current},
                               {"velocity", p.velocity},
                               {"force", p.force},
                               {"force_pressure", p.force_pressure},
                               {"force_wall", p.force_wall},
                               {"force_gas", p.force_gas},
                               {"dp", p.dp},
                               {"dp_viscous", p.dp_viscous},
                               {"flow", p.flow},
                               {"wall_velocity", p.wall_velocity},
                               {"inductance", p.inductance},
                               {"gaps", gaps}});
    }
    rheomag::app::print_json(out, 2);
    return;
  }
  rheomag::app::print(
      "damper %s, fluid %s, gap wall %s; gas force %.4g N (%.4g .. %.4g N over the "
      "stroke)\n",
      c.name.c_str(), chain.fluid().name.c_str(),
      std::string(valve::kGapWallNames.name(options.gap_wall)).c_str(), points.front().force_gas,
      gas_extended, gas_compressed);
  rheomag::app::print("%8s %10s %12s %12s %12s %12s\n", "I [A]", "v [m/s]", "F [N]", "F_dp [N]",
                      "F_wall [N]", "dp [bar]");
  for (const auto& p : points)
    rheomag::app::print("%8.4g %10.4g %12.5g %12.5g %12.5g %12.5g\n", p.current, p.velocity,
                        p.force, p.force_pressure, p.force_wall, p.dp * 1e-5);
}

const bool registered = rheomag::app::register_command([](CLI::App& root) {
  auto o = std::make_shared<DamperCli>();
  CLI::App* cmd = root.add_subcommand(
      "damper",
      "Force-velocity curves of a flow-mode MR damper piston case: the FE field at each\n"
      "current, the exact mixed-mode (pressure + moving wall) Bingham / Herschel-Bulkley law\n"
      "integrated along every annular gap of the piston with the local tau_y(B(z)), then the\n"
      "force F = dp A_piston + wall shear + gas pressure x rod area. Velocity > 0 compresses\n"
      "(either sign). SI units. The case needs a [damper] table. See docs/dampers.md.");
  cmd->add_option("case", o->case_file, "Case file (.toml)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--current", o->currents,
                  "Coil currents [A], comma-separated (default: the case's circuit current)")
      ->delimiter(',');
  cmd->add_option("--velocity", o->velocities,
                  "Piston velocities [m/s], comma-separated (default: [damper] velocity)")
      ->delimiter(',');
  cmd->add_flag("--json", o->json, "Print one JSON object to stdout");
  cmd->callback([o] { run_damper(*o); });
});

}  // namespace
