// rheomag flow: pressure drop of one MR-fluid gap (annular, slit or radial) at a given yield
// stress and flow rate, optionally with the inner wall moving (mixed mode). The physics lives in
// fluid/; this file only maps options to it.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/command.hpp"
#include "core/enum_names.hpp"
#include "core/error.hpp"
#include "fluid/mixed_mode.hpp"
#include "fluid/radial_bingham.hpp"
#include "fluid/slit_bingham.hpp"

namespace {

enum class GapKind { annular, slit, radial };
enum class FlowModel { exact, approx };

constexpr auto kGapKindNames = rheomag::enum_names<GapKind>(
    {{GapKind::annular, "annular"}, {GapKind::slit, "slit"}, {GapKind::radial, "radial"}});
constexpr auto kFlowModelNames =
    rheomag::enum_names<FlowModel>({{FlowModel::exact, "exact"}, {FlowModel::approx, "approx"}});

struct FlowOptions {
  GapKind kind = GapKind::annular;
  FlowModel model = FlowModel::exact;
  double gap = 0, length = 0, radius = 0, width = 0, r_in = 0, r_out = 0;
  double tau_y = 0, viscosity = 0, flow = 0, wall_velocity = 0, flow_index = 1.0;
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

/// The result of one gap: the drop, plus the mixed-mode details for annular and slit gaps.
struct FlowResult {
  rheomag::fluid::GapPressureDrop drop;
  std::optional<rheomag::fluid::MixedModeDrop> mixed;
};

FlowResult compute(const CLI::App& cmd, const FlowOptions& o) {
  using namespace rheomag::fluid;
  const std::string_view kind = kGapKindNames.name(o.kind);
  for (const char* option : {"--length", "--radius", "--width", "--r-in", "--r-out"}) {
    const std::string_view name(option);
    const bool used = o.kind == GapKind::annular ? (name == "--length" || name == "--radius")
                      : o.kind == GapKind::slit  ? (name == "--length" || name == "--width")
                                                 : (name == "--r-in" || name == "--r-out");
    used ? require(cmd, option, kind) : forbid(cmd, option, kind);
  }
  const bool moving = o.wall_velocity != 0.0;
  if (o.model == FlowModel::approx && (moving || o.flow_index != 1.0 || o.kind == GapKind::slit))
    throw rheomag::InputError(
        "--model approx (paper 000) is for a still-walled Bingham annular or radial gap only");
  if (o.kind == GapKind::radial && (moving || o.flow_index != 1.0))
    throw rheomag::InputError(
        "--wall-velocity and --flow-index apply to --kind annular and slit only");
  const GapRheology fluid{o.tau_y, o.viscosity, o.flow_index};
  FlowResult result;
  if (o.kind == GapKind::radial) {
    const RadialGeometry g{o.gap, o.r_in, o.r_out};
    result.drop = radial_bingham(g, o.tau_y, o.viscosity, o.flow,
                                 o.model == FlowModel::exact ? SlitLaw::exact : SlitLaw::paper000);
  } else if (o.model == FlowModel::approx) {
    result.drop =
        annulus_paper000(AnnulusGeometry{o.gap, o.radius, o.length}, o.tau_y, o.viscosity, o.flow);
  } else {
    result.mixed = o.kind == GapKind::annular
                       ? annulus_mixed_mode(AnnulusGeometry{o.gap, o.radius, o.length}, fluid,
                                            o.wall_velocity, o.flow)
                       : slit_mixed_mode(SlitGeometry{o.gap, o.width, o.length}, fluid,
                                         o.wall_velocity, o.flow);
    result.drop = result.mixed->drop;
  }
  return result;
}

void run_flow(const CLI::App& cmd, const FlowOptions& o) {
  const FlowResult result = compute(cmd, o);
  const auto& d = result.drop;
  const std::string_view kind = kGapKindNames.name(o.kind);
  const std::string_view model = kFlowModelNames.name(o.model);
  const std::string regime =
      result.mixed ? std::string(rheomag::fluid::kMixedRegimeNames.name(result.mixed->regime))
                   : std::string(o.tau_y > 0.0 ? "floating_plug" : "fully_yielded");
  if (o.json) {
    rheomag::app::print(
        "{\"kind\": \"%s\", \"model\": \"%s\", \"wall_velocity\": %.12g, \"regime\": \"%s\", "
        "\"dp\": %.12g, \"dp_yield\": %.12g, \"dp_viscous\": %.12g, \"plug_fraction\": %.12g, "
        "\"bingham_number\": %.12g",
        std::string(kind).c_str(), std::string(model).c_str(), o.wall_velocity, regime.c_str(),
        d.dp, d.dp_yield, d.dp_viscous, d.plug_fraction, d.bingham_number);
    if (result.mixed)
      rheomag::app::print(
          ", \"plug_start\": %.12g, \"plug_end\": %.12g, \"moving_wall_stress\": %.12g, "
          "\"fixed_wall_stress\": %.12g, \"moving_wall_force\": %.12g",
          result.mixed->plug_start, result.mixed->plug_end, result.mixed->moving_wall_stress,
          result.mixed->fixed_wall_stress, result.mixed->moving_wall_force);
    rheomag::app::print("}\n");
    return;
  }
  rheomag::app::print("%s gap, %s model, wall velocity %g m/s\n", std::string(kind).c_str(),
                      std::string(model).c_str(), o.wall_velocity);
  rheomag::app::print("  pressure drop        dp            = %.6g Pa (%.4g bar)\n", d.dp,
                      d.dp * 1e-5);
  rheomag::app::print("  viscous part         dp_viscous    = %.6g Pa\n", d.dp_viscous);
  rheomag::app::print("  yield part           dp_yield      = %.6g Pa\n", d.dp_yield);
  rheomag::app::print("  regime                               %s%s\n", regime.c_str(),
                      o.kind == GapKind::radial ? " (at the mean radius)" : "");
  rheomag::app::print("  plug fraction        delta         = %.6g%s\n", d.plug_fraction,
                      o.kind == GapKind::radial ? " (at the mean radius)" : "");
  rheomag::app::print("  Bingham number       Bi            = %.6g%s\n", d.bingham_number,
                      o.kind == GapKind::radial ? " (at the mean radius)" : "");
  if (result.mixed) {
    rheomag::app::print("  plug                 from %.6g to %.6g m off the moving wall\n",
                        result.mixed->plug_start, result.mixed->plug_end);
    rheomag::app::print("  moving-wall force    F_wall        = %.6g N (shear stress %.6g Pa)\n",
                        result.mixed->moving_wall_force, result.mixed->moving_wall_stress);
  }
}

const bool registered = rheomag::app::register_command([](CLI::App& root) {
  auto options = std::make_shared<FlowOptions>();
  CLI::App* cmd = root.add_subcommand(
      "flow",
      "Pressure drop of one MR-fluid gap (Bingham / Herschel-Bulkley) at a given yield stress\n"
      "and flow. All values SI. annular: axial flow through an annulus of radial clearance --gap\n"
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
           options->kind = kGapKindNames.parse(kind, "--kind");
         },
         "Gap kind: annular, slit or radial")
      ->required()
      ->check(CLI::IsMember({"annular", "slit", "radial"}));
  cmd->add_option("--gap", options->gap, "Gap clearance h [m]")->required();
  cmd->add_option("--length", options->length, "annular, slit: active length L [m]");
  cmd->add_option("--radius", options->radius, "annular: mean radius R of the gap [m]");
  cmd->add_option("--width", options->width, "slit: width b across the flow [m]");
  cmd->add_option("--r-in", options->r_in, "radial: inner radius [m]");
  cmd->add_option("--r-out", options->r_out, "radial: outer radius [m]");
  cmd->add_option("--tau-y", options->tau_y, "Yield stress tau_y [Pa] (>= 0)")->required();
  cmd->add_option("--viscosity", options->viscosity,
                  "Plastic viscosity mu [Pa s] (consistency K [Pa s^n] with --flow-index)")
      ->required();
  cmd->add_option("--flow-index", options->flow_index,
                  "Herschel-Bulkley exponent n (default 1: Bingham; annular and slit)");
  cmd->add_option("--flow", options->flow, "Volume flow rate Q [m^3/s]")->required();
  cmd->add_option("--wall-velocity", options->wall_velocity,
                  "Velocity U of the inner (moving) wall along the flow [m/s] (default 0)");
  cmd->add_option_function<std::string>(
         "--model",
         [options](const std::string& model) {
           options->model = kFlowModelNames.parse(model, "--model");
         },
         "exact (default) or approx (paper 000 eqs. 2-3)")
      ->check(CLI::IsMember({"exact", "approx"}));
  cmd->add_flag("--json", options->json, "Print one JSON object to stdout");
  cmd->callback([cmd, options] { run_flow(*cmd, *options); });
});

}  // namespace
