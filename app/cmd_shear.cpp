// rheomag shear: torque of a shear-mode MR device (drum or disc) at a given yield stress and
// speed. The physics lives in fluid/shear_mode; this file only maps options to it.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "core/enum_names.hpp"
#include "core/error.hpp"
#include "fluid/shear_mode.hpp"

namespace {

enum class ShearKind { drum, disc };

constexpr auto kShearKindNames =
    rheomag::enum_names<ShearKind>({{ShearKind::drum, "drum"}, {ShearKind::disc, "disc"}});

struct ShearOptions {
  ShearKind kind = ShearKind::drum;
  double r_in = 0, r_out = 0, length = 0, gap = 0;
  int faces = 2;
  double tau_y = 0, viscosity = 0, flow_index = 1.0, speed = 0;
  bool json = false;
};

void check_options(const CLI::App& cmd, const ShearOptions& o) {
  const std::string kind(kShearKindNames.name(o.kind));
  const char* needed = o.kind == ShearKind::drum ? "--length" : "--gap";
  if (cmd.count(needed) == 0) throw rheomag::InputError("--kind " + kind + " needs " + needed);
  const std::vector<const char*> other = o.kind == ShearKind::drum
                                             ? std::vector<const char*>{"--gap", "--faces"}
                                             : std::vector<const char*>{"--length"};
  for (const char* option : other)
    if (cmd.count(option) != 0)
      throw rheomag::InputError(std::string(option) + " does not apply to --kind " + kind);
}

void run_shear(const CLI::App& cmd, const ShearOptions& o) {
  using namespace rheomag::fluid;
  check_options(cmd, o);
  const GapRheology fluid{o.tau_y, o.viscosity, o.flow_index};
  const ShearTorque t =
      o.kind == ShearKind::drum
          ? drum_torque(DrumGeometry{o.r_in, o.r_out, o.length}, fluid, o.speed)
          : disc_torque(DiscGeometry{o.r_in, o.r_out, o.gap, o.faces}, fluid, o.speed);
  const std::string kind(kShearKindNames.name(o.kind));
  if (o.json) {
    rheomag::app::print(
        "{\"kind\": \"%s\", \"speed\": %.12g, \"torque\": %.12g, \"torque_yield\": %.12g, "
        "\"torque_viscous\": %.12g, \"breakaway_torque\": %.12g, \"yielded_fraction\": %.12g, "
        "\"yield_radius\": %.12g}\n",
        kind.c_str(), o.speed, t.torque, t.torque_yield, t.torque_viscous, t.breakaway_torque,
        t.yielded_fraction, t.yield_radius);
    return;
  }
  rheomag::app::print("%s, speed %g rad/s\n", kind.c_str(), o.speed);
  rheomag::app::print("  torque               T             = %.6g N m\n", t.torque);
  rheomag::app::print("  viscous part         T_viscous     = %.6g N m\n", t.torque_viscous);
  rheomag::app::print("  yield part           T_yield       = %.6g N m\n", t.torque_yield);
  rheomag::app::print("  breakaway torque     T(0+)         = %.6g N m\n", t.breakaway_torque);
  rheomag::app::print("  yielded fraction                   = %.6g\n", t.yielded_fraction);
  if (o.kind == ShearKind::drum)
    rheomag::app::print("  yield radius         r_y           = %.6g m\n", t.yield_radius);
}

const bool registered = rheomag::app::register_command([](CLI::App& root) {
  auto options = std::make_shared<ShearOptions>();
  CLI::App* cmd = root.add_subcommand(
      "shear",
      "Torque of a shear-mode MR device (Bingham / Herschel-Bulkley) at a given yield stress\n"
      "and speed. All values SI. drum: fluid between an inner cylinder of radius --r-in\n"
      "rotating at --speed and a fixed outer cylinder --r-out, over --length (exact Couette\n"
      "flow, partial yielding where the stress, falling as 1/r^2, drops below tau_y). disc: a\n"
      "disc ring --r-in..--r-out rotating --gap away from --faces fixed faces (fully yielded\n"
      "for any speed). A negative speed turns the other way (negative torque); speed 0 gives\n"
      "the breakaway (holding) torque. Output: torque, torque_viscous = the tau_y = 0 torque at\n"
      "the same speed, torque_yield = torque - torque_viscous, breakaway_torque,\n"
      "yielded_fraction. See docs/fluid.md.");
  cmd->add_option_function<std::string>(
         "--kind",
         [options](const std::string& kind) {
           options->kind = kShearKindNames.parse(kind, "--kind");
         },
         "Device kind: drum or disc")
      ->required()
      ->check(CLI::IsMember({"drum", "disc"}));
  cmd->add_option("--r-in", options->r_in, "Inner radius [m]")->required();
  cmd->add_option("--r-out", options->r_out, "Outer radius [m]")->required();
  cmd->add_option("--length", options->length, "drum: axial length [m]");
  cmd->add_option("--gap", options->gap, "disc: axial gap to each face [m]");
  cmd->add_option("--faces", options->faces, "disc: number of sheared faces (default 2)");
  cmd->add_option("--tau-y", options->tau_y, "Yield stress tau_y [Pa] (>= 0)")->required();
  cmd->add_option("--viscosity", options->viscosity,
                  "Plastic viscosity mu [Pa s] (consistency K [Pa s^n] with --flow-index)")
      ->required();
  cmd->add_option("--flow-index", options->flow_index,
                  "Herschel-Bulkley exponent n (default 1: Bingham)");
  cmd->add_option("--speed", options->speed, "Angular speed omega of the rotor [rad/s]")
      ->required();
  cmd->add_flag("--json", options->json, "Print one JSON object to stdout");
  cmd->callback([cmd, options] { run_shear(*cmd, *options); });
});

}  // namespace
