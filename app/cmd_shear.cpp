// rheomag shear: torque of a shear-mode MR device (drum or disc) at a given yield stress and
// speed. The physics lives in fluid/shear_device.hpp; this file only maps options to it.

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "core/error.hpp"
#include "fluid/shear_device.hpp"

namespace {

using rheomag::fluid::kShearKindNames;
using rheomag::fluid::ShearKind;

/// The options of `rheomag shear`: the device and its speed, and the output form.
struct ShearOptions {
  rheomag::fluid::ShearDeviceInput device;
  bool json = false;
};

void check_options(const CLI::App& cmd, const ShearOptions& o) {
  const std::string kind(kShearKindNames.name(o.device.kind));
  const char* needed = o.device.kind == ShearKind::drum ? "--length" : "--gap";
  if (cmd.count(needed) == 0) throw rheomag::InputError("--kind " + kind + " needs " + needed);
  const std::vector<const char*> other = o.device.kind == ShearKind::drum
                                             ? std::vector<const char*>{"--gap", "--faces"}
                                             : std::vector<const char*>{"--length"};
  for (const char* option : other)
    if (cmd.count(option) != 0)
      throw rheomag::InputError(std::string(option) + " does not apply to --kind " + kind);
}

void run_shear(const CLI::App& cmd, const ShearOptions& o) {
  using namespace rheomag::fluid;
  check_options(cmd, o);
  const ShearTorque t = shear_device_torque(o.device);
  std::cout << (o.json ? shear_device_json(o.device, t) : shear_device_text(o.device, t));
}

const bool shear_registered = rheomag::app::register_command([](CLI::App& root) {
  auto options = std::make_shared<ShearOptions>();
  CLI::App* cmd = root.add_subcommand(
      "shear",
      "Torque of a shear-mode MR device (Bingham / Herschel-Bulkley) at a given yield stress\n"
      "and speed. SI unless a unit is written. drum: fluid between an inner cylinder of radius "
      "--r-in\n"
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
           options->device.kind = kShearKindNames.parse(kind, "--kind");
         },
         "Device kind: drum or disc")
      ->required()
      ->check(CLI::IsMember({"drum", "disc"}));
  rheomag::app::add_quantity(cmd, "--r-in", options->device.r_in, rheomag::QuantityKind::length,
                             "Inner radius")
      ->required();
  rheomag::app::add_quantity(cmd, "--r-out", options->device.r_out, rheomag::QuantityKind::length,
                             "Outer radius")
      ->required();
  rheomag::app::add_quantity(cmd, "--length", options->device.length, rheomag::QuantityKind::length,
                             "drum: axial length");
  rheomag::app::add_quantity(cmd, "--gap", options->device.gap, rheomag::QuantityKind::length,
                             "disc: axial gap to each face");
  cmd->add_option("--faces", options->device.faces, "disc: number of sheared faces (default 2)");
  rheomag::app::add_quantity(cmd, "--tau-y", options->device.tau_y, rheomag::QuantityKind::pressure,
                             "Yield stress tau_y (>= 0)")
      ->required();
  cmd->add_option("--viscosity", options->device.viscosity,
                  "Plastic viscosity mu [Pa s] (consistency K [Pa s^n] with --flow-index)")
      ->required();
  cmd->add_option("--flow-index", options->device.flow_index,
                  "Herschel-Bulkley exponent n (default 1: Bingham)");
  rheomag::app::add_quantity(cmd, "--speed", options->device.speed,
                             rheomag::QuantityKind::angular_speed,
                             "Angular speed omega of the rotor")
      ->required();
  cmd->add_flag("--json", options->json, "Print one JSON object to stdout");
  cmd->callback([cmd, options] { run_shear(*cmd, *options); });
});

}  // namespace
