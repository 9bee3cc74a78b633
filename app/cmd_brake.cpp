// rheomag brake CASE: torque-speed curves of a shear-mode brake or rotary damper case at a list
// of coil currents (FE field -> drum and disc gaps -> torque). Logic in valve/brake.hpp.

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
#include "valve/brake.hpp"

namespace {

struct BrakeCli {
  std::string case_file;
  std::vector<double> currents, speeds;
  bool json = false;
};

nlohmann::json torque_json(const rheomag::fluid::ShearTorque& t) {
  return {{"torque", t.torque},
          {"torque_yield", t.torque_yield},
          {"torque_viscous", t.torque_viscous},
          {"breakaway_torque", t.breakaway_torque},
          {"yielded_fraction", t.yielded_fraction}};
}

void run_brake(const BrakeCli& o) {
  using namespace rheomag;
  const auto c = cases::load_case(o.case_file);
  const valve::BrakeOptions options = valve::read_brake_options(c);
  std::vector<double> currents = o.currents;
  if (currents.empty())
    for (const auto& circuit : c.problem.circuits) currents = {circuit.current};
  const std::vector<double> speeds = o.speeds.empty() ? options.speeds : o.speeds;
  if (speeds.empty())
    throw InputError(o.case_file +
                     ": no speed: pass --speed W[,W...] (rad/s) or set [brake] "
                     "speed in the case");
  valve::BrakeChain chain(c, options);
  const auto points = chain.evaluate(currents, speeds);
  if (o.json) {
    nlohmann::json out;
    out["case"] = c.name;
    out["fluid"] = chain.fluid().name;
    out["points"] = nlohmann::json::array();
    for (const auto& p : points) {
      nlohmann::json gaps = nlohmann::json::array();
      for (const auto& g : p.gaps) {
        nlohmann::json gap = torque_json(g.torque);
        gap["name"] = g.name;
        gap["kind"] = g.kind;
        gap["b_average"] = g.b_average;
        gaps.push_back(gap);
      }
      nlohmann::json point = torque_json(p.torque);
      point["current"] = p.current;
      point["speed"] = p.speed;
      point["inductance"] = p.inductance;
      point["gaps"] = gaps;
      out["points"].push_back(point);
    }
    rheomag::app::print_json(out, 2);
    return;
  }
  rheomag::app::print("brake %s, fluid %s\n", c.name.c_str(), chain.fluid().name.c_str());
  rheomag::app::print("%8s %12s %12s %12s %12s %12s\n", "I [A]", "w [rad/s]", "T [N m]", "T_yield",
                      "T_viscous", "T(0+) [N m]");
  for (const auto& p : points)
    rheomag::app::print("%8.4g %12.4g %12.5g %12.5g %12.5g %12.5g\n", p.current, p.speed,
                        p.torque.torque, p.torque.torque_yield, p.torque.torque_viscous,
                        p.torque.breakaway_torque);
}

const bool registered = rheomag::app::register_command([](CLI::App& root) {
  auto o = std::make_shared<BrakeCli>();
  CLI::App* cmd = root.add_subcommand(
      "brake",
      "Torque-speed curves of a shear-mode MR brake or rotary damper case: the FE field at\n"
      "each current; every annular gap region is a drum (inner wall turning, exact Couette\n"
      "flow with partial yielding), every radial gap region one sheared disc face, each with\n"
      "the local tau_y(B). Speed in rad/s (either sign; 0 gives the breakaway torque). SI\n"
      "units. See docs/dampers.md.");
  cmd->add_option("case", o->case_file, "Case file (.toml)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--current", o->currents,
                  "Coil currents [A], comma-separated (default: the case's circuit current)")
      ->delimiter(',');
  cmd->add_option("--speed", o->speeds,
                  "Rotor speeds [rad/s], comma-separated (default: [brake] speed)")
      ->delimiter(',');
  cmd->add_flag("--json", o->json, "Print one JSON object to stdout");
  cmd->callback([o] { run_brake(*o); });
});

}  // namespace
