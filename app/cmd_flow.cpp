// rheomag flow: pressure drop of one MR-fluid gap (annular, slit or radial) at a given yield
// stress and flow rate, optionally with the inner wall moving (mixed mode). The physics lives in
// fluid/gap_flow.hpp; this file only maps options to it.

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <string>
#include <string_view>

#include "app/command.hpp"
#include "core/error.hpp"
#include "fluid/gap_flow.hpp"

namespace {

using rheomag::fluid::FlowGapKind;
using rheomag::fluid::kFlowGapKindNames;
using rheomag::fluid::kFlowModelNames;

/// The options of `rheomag flow`: the gap and its flow, and the output form.
struct FlowOptions {
  rheomag::fluid::GapFlowInput gap;
  bool json = false;
};

void require(const CLI::App& cmd, const char* option, std::string_view kind) {
  if (cmd.count(option) == 0)
    throw rheomag::InputError("--kind " + std::string(kind) + " needs " + option);
}

void forbid(const CLI::App& cmd, const char* option, std::string_view kind) {
  if (cmd.count(option) != 0)
    throw rheomag::InputError(std::string(option) + " does not apply to --kind " +
                              std::string(kind));
}

void run_flow(const CLI::App& cmd, const FlowOptions& o) {
  const FlowGapKind kind = o.gap.kind;
  for (const char* option : {"--length", "--radius", "--width", "--r-in", "--r-out"}) {
    const std::string_view name(option);
    const bool used = kind == FlowGapKind::annular ? (name == "--length" || name == "--radius")
                      : kind == FlowGapKind::slit  ? (name == "--length" || name == "--width")
                                                   : (name == "--r-in" || name == "--r-out");
    used ? require(cmd, option, kFlowGapKindNames.name(kind))
         : forbid(cmd, option, kFlowGapKindNames.name(kind));
  }
  const rheomag::fluid::GapFlowResult result = rheomag::fluid::gap_flow(o.gap);
  if (o.json)
    rheomag::app::print_json(rheomag::fluid::gap_flow_json(result), 2);
  else
    std::cout << rheomag::fluid::gap_flow_text(result);
}

const bool flow_registered = rheomag::app::register_command([](CLI::App& root) {
  auto options = std::make_shared<FlowOptions>();
  CLI::App* cmd = root.add_subcommand(
      "flow",
      "Pressure drop of one MR-fluid gap (Bingham / Herschel-Bulkley) at a given yield stress\n"
      "and flow. SI unless a unit is written. annular: axial flow through an annulus of radial "
      "clearance --gap\n"
      "about the mean radius --radius, over --length. slit: parallel plates --gap apart, --width\n"
      "across, --length along the flow. radial: flow through a disk gap of axial clearance --gap\n"
      "between --r-in and --r-out.\n"
      "--wall-velocity U (annular, slit): the inner wall (the piston) slides at U along the flow\n"
      "direction (negative: against it); --flow is counted in the fixed (outer) wall's frame and\n"
      "may then have either sign, and dp may come out negative (mixed mode, exact in every\n"
      "regime: plug on the moving wall, on the fixed wall, floating, or none).\n"
      "Models: exact = exact solution (annulus with curvature; radial: local exact slit law\n"
      "integrated along r). approx = paper 000 eqs. (2)-(3) (still-walled Bingham only).\n"
      "Output: dp, dp_viscous = the tau_y = 0 dp at the same Q (and U), dp_yield = dp -\n"
      "dp_viscous, regime, plug_fraction = plug thickness/gap, bingham_number = tau_y /\n"
      "(K (V/h)^n), V = max(|Q|/A, |U|). See docs/fluid.md.");
  cmd->add_option_function<std::string>(
         "--kind",
         [options](const std::string& kind) {
           options->gap.kind = kFlowGapKindNames.parse(kind, "--kind");
         },
         "Gap kind: annular, slit or radial")
      ->required()
      ->check(CLI::IsMember({"annular", "slit", "radial"}));
  rheomag::app::add_quantity(cmd, "--gap", options->gap.gap, rheomag::QuantityKind::length,
                             "Gap clearance h")
      ->required();
  rheomag::app::add_quantity(cmd, "--length", options->gap.length, rheomag::QuantityKind::length,
                             "annular, slit: active length L");
  rheomag::app::add_quantity(cmd, "--radius", options->gap.radius, rheomag::QuantityKind::length,
                             "annular: mean radius R of the gap");
  rheomag::app::add_quantity(cmd, "--width", options->gap.width, rheomag::QuantityKind::length,
                             "slit: width b across the flow");
  rheomag::app::add_quantity(cmd, "--r-in", options->gap.r_in, rheomag::QuantityKind::length,
                             "radial: inner radius");
  rheomag::app::add_quantity(cmd, "--r-out", options->gap.r_out, rheomag::QuantityKind::length,
                             "radial: outer radius");
  rheomag::app::add_quantity(cmd, "--tau-y", options->gap.tau_y, rheomag::QuantityKind::pressure,
                             "Yield stress tau_y (>= 0)")
      ->required();
  cmd->add_option("--viscosity", options->gap.viscosity,
                  "Plastic viscosity mu [Pa s] (consistency K [Pa s^n] with --flow-index)")
      ->required();
  cmd->add_option("--flow-index", options->gap.flow_index,
                  "Herschel-Bulkley exponent n (default 1: Bingham; annular and slit)");
  rheomag::app::add_quantity(cmd, "--flow", options->gap.flow, rheomag::QuantityKind::flow,
                             "Volume flow rate Q")
      ->required();
  rheomag::app::add_quantity(cmd, "--wall-velocity", options->gap.wall_velocity,
                             rheomag::QuantityKind::velocity,
                             "Velocity U of the inner (moving) wall along the flow (default 0)");
  cmd->add_option_function<std::string>(
         "--model",
         [options](const std::string& model) {
           options->gap.model = kFlowModelNames.parse(model, "--model");
         },
         "exact (default) or approx (paper 000 eqs. 2-3)")
      ->check(CLI::IsMember({"exact", "approx"}));
  cmd->add_flag("--json", options->json, "Print one JSON object to stdout");
  cmd->callback([cmd, options] { run_flow(*cmd, *options); });
});

}  // namespace
