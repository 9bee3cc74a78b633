// rheomag valve CASE: steady-state pressure drop of a case's valve (its magnetised gaps, listed
// passages and minor losses in series, field from the FE solve) at a list of currents and flow
// rates, plus the coil. Logic in
// fluid/valve_chain.hpp.

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "case/case_file.hpp"
#include "core/error.hpp"
#include "valve/valve_chain.hpp"

namespace {

struct ValveCli {
  std::string case_file;
  std::vector<double> currents, flows;
  std::string wire;
  double temperature = NAN;
  bool json = false;
};

nlohmann::json segment_json(const rheomag::valve::SegmentResult& s) {
  const auto& d = s.drop.integrated;
  return {{"name", s.name},
          {"kind", std::string(rheomag::valve::kSegmentKindNames.name(s.kind))},
          {"b_average", s.b_average},
          {"dp", d.dp},
          {"dp_yield", d.dp_yield},
          {"dp_viscous", d.dp_viscous},
          {"dp_average_b", s.drop.average_b.dp},
          {"plug_fraction", d.plug_fraction},
          {"bingham_number", d.bingham_number},
          {"reynolds_number", s.kind == rheomag::valve::SegmentKind::passage
                                  ? nlohmann::json(s.reynolds_number)
                                  : nullptr}};
}

void run_valve(const ValveCli& o) {
  using namespace rheomag;
  const auto c = cases::load_case(o.case_file);
  valve::ValveOptions options = valve::read_valve_options(c);
  if (!o.wire.empty()) {
    try {
      options.wire_diameter = cases::wire_diameter(o.wire);
    } catch (const InputError& e) {
      throw InputError(std::string("--wire: ") + e.what());
    }
    options.wire = o.wire;
  }
  if (!std::isnan(o.temperature)) options.temperature = o.temperature;
  std::vector<double> currents = o.currents;
  if (currents.empty())
    for (const auto& circuit : c.problem.circuits) currents = {circuit.current};
  std::vector<double> flows = o.flows.empty() ? options.flows : o.flows;
  if (flows.empty())
    throw InputError(o.case_file + ": no flow rate: pass --flow Q[,Q...] (m^3/s) or set " +
                     "[valve] flow in the case");
  valve::ValveChain chain(c, options);
  const auto points = chain.evaluate(currents, flows);
  // The coil at the largest current (its secant inductance from the FE solve there).
  const valve::ValvePoint* peak = &points.front();
  for (const auto& p : points)
    if (std::abs(p.current) > std::abs(peak->current)) peak = &p;
  const bool have_wire = !options.wire.empty();
  valve::CoilProperties coil;
  if (have_wire) coil = chain.coil(peak->current, peak->inductance);

  if (o.json) {
    nlohmann::json out;
    out["case"] = c.name;
    out["fluid"] = chain.fluid().name;
    out["points"] = nlohmann::json::array();
    for (const auto& p : points) {
      nlohmann::json segments = nlohmann::json::array();
      for (const auto& s : p.segments) segments.push_back(segment_json(s));
      out["points"].push_back({{"current", p.current},
                               {"flow", p.flow},
                               {"dp_total", p.dp_total},
                               {"dp_yield", p.dp_yield},
                               {"dp_viscous", p.dp_viscous},
                               {"dp_total_average_b", p.dp_total_average_b},
                               {"inductance", p.inductance},
                               {"segments", segments}});
    }
    nlohmann::json coil_json = {{"turns", chain.turns()},
                                {"current", peak->current},
                                {"inductance", peak->inductance},
                                {"wire", have_wire ? nlohmann::json(options.wire) : nullptr},
                                {"temperature", options.temperature}};
    if (have_wire) {
      coil_json["resistance"] = coil.resistance;
      coil_json["time_constant"] = coil.time_constant;
      coil_json["power"] = coil.power;
      coil_json["wire_length"] = coil.wire_length;
      coil_json["copper_fill"] = coil.copper_fill;
      coil_json["current_density"] = coil.current_density;
    } else {
      for (const char* key : {"resistance", "time_constant", "power"}) coil_json[key] = nullptr;
    }
    // L(I) from the FE solve at each requested current (one row per current).
    nlohmann::json table = nlohmann::json::array();
    for (std::size_t i = 0; i < points.size(); i += flows.size())
      table.push_back({{"current", points[i].current},
                       {"flux_linkage", points[i].flux_linkage},
                       {"inductance", points[i].inductance},
                       {"incremental_inductance", points[i].incremental_inductance}});
    coil_json["inductance_table"] = table;
    out["coil"] = coil_json;
    rheomag::app::print_json(out, 2);
    return;
  }
  rheomag::app::print("valve %s, fluid %s\n", c.name.c_str(), chain.fluid().name.c_str());
  rheomag::app::print("%10s %12s %12s %12s %12s %14s\n", "I [A]", "Q [m3/s]", "dp [bar]",
                      "yield [bar]", "visc. [bar]", "avg-B [bar]");
  for (const auto& p : points)
    rheomag::app::print("%10.4g %12.4g %12.5g %12.5g %12.5g %14.5g\n", p.current, p.flow,
                        p.dp_total * 1e-5, p.dp_yield * 1e-5, p.dp_viscous * 1e-5,
                        p.dp_total_average_b * 1e-5);
  rheomag::app::print("%10s %14s %14s %16s\n", "I [A]", "lambda [Wb]", "L = l/I [H]", "dl/dI [H]");
  for (std::size_t i = 0; i < points.size(); i += flows.size())
    rheomag::app::print("%10.4g %14.5g %14.5g %16.5g\n", points[i].current, points[i].flux_linkage,
                        points[i].inductance, points[i].incremental_inductance);
  rheomag::app::print("coil: %g turns, L = %.4g H at %g A", chain.turns(), peak->inductance,
                      peak->current);
  if (have_wire)
    rheomag::app::print(
        ", R = %.4g Ohm (%s, %g C), L/R = %.4g s, P = %.4g W, J = %.4g A/mm^2, copper fill "
        "%.3f\n",
        coil.resistance, options.wire.c_str(), options.temperature, coil.time_constant, coil.power,
        coil.current_density * 1e-6, coil.copper_fill);
  else
    rheomag::app::print("; R, L/R and power need the wire: [valve] wire = \"AWG 24\" or --wire\n");
}

const bool registered = rheomag::app::register_command([](CLI::App& root) {
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
  cmd->add_option("--current", o->currents,
                  "Coil currents [A], comma-separated "
                  "(default: the case's circuit current)")
      ->delimiter(',');
  cmd->add_option("--flow", o->flows,
                  "Flow rates [m^3/s], comma-separated "
                  "(default: [valve] flow)")
      ->delimiter(',');
  cmd->add_option("--wire", o->wire, "Wire, e.g. \"AWG 24\" or \"0.5 mm\" (default: [valve] wire)")
      ->check(rheomag::app::non_empty());
  cmd->add_option("--temperature", o->temperature, "Coil temperature [C] (default 20)");
  cmd->add_flag("--json", o->json, "Print one JSON object to stdout");
  cmd->callback([o] { run_valve(*o); });
});

}  // namespace
