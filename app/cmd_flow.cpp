// rheomag flow: pressure drop of one MR-fluid gap (annular or radial) at a given yield stress
// and flow rate. The physics lives in fluid/; this file only maps options to it.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>

#include "app/command.hpp"
#include "core/error.hpp"
#include "fluid/annulus_bingham.hpp"
#include "fluid/radial_bingham.hpp"
#include "fluid/slit_bingham.hpp"

namespace {

enum class GapKind { annular, radial };
enum class FlowModel { exact, approx };

struct FlowOptions {
  GapKind kind = GapKind::annular;
  FlowModel model = FlowModel::exact;
  double gap = 0, length = 0, radius = 0, r_in = 0, r_out = 0;
  double tau_y = 0, viscosity = 0, flow = 0;
  bool json = false;
};

void require(const CLI::App& cmd, const char* option, const char* kind) {
  if (cmd.count(option) == 0)
    throw rheomag::InputError(std::string("--kind ") + kind + " needs " + option);
}

void forbid(const CLI::App& cmd, const char* option, const char* kind) {
  if (cmd.count(option) != 0)
    throw rheomag::InputError(std::string(option) + " does not apply to --kind " + kind);
}

void run_flow(const CLI::App& cmd, const FlowOptions& o) {
  using namespace rheomag::fluid;
  GapPressureDrop result;
  const char* kind = o.kind == GapKind::annular ? "annular" : "radial";
  if (o.kind == GapKind::annular) {
    require(cmd, "--length", kind);
    require(cmd, "--radius", kind);
    forbid(cmd, "--r-in", kind);
    forbid(cmd, "--r-out", kind);
    const AnnulusGeometry g{o.gap, o.radius, o.length};
    result = o.model == FlowModel::exact ? annulus_bingham(g, o.tau_y, o.viscosity, o.flow)
                                         : annulus_paper000(g, o.tau_y, o.viscosity, o.flow);
  } else {
    require(cmd, "--r-in", kind);
    require(cmd, "--r-out", kind);
    forbid(cmd, "--length", kind);
    forbid(cmd, "--radius", kind);
    const RadialGeometry g{o.gap, o.r_in, o.r_out};
    result = radial_bingham(g, o.tau_y, o.viscosity, o.flow,
                            o.model == FlowModel::exact ? SlitLaw::exact : SlitLaw::paper000);
  }
  const char* model = o.model == FlowModel::exact ? "exact" : "approx";
  if (o.json) {
    std::printf(
        "{\"kind\": \"%s\", \"model\": \"%s\", \"dp\": %.12g, \"dp_yield\": %.12g, "
        "\"dp_viscous\": %.12g, \"plug_fraction\": %.12g, \"bingham_number\": %.12g}\n",
        kind, model, result.dp, result.dp_yield, result.dp_viscous, result.plug_fraction,
        result.bingham_number);
  } else {
    std::printf("%s gap, %s model\n", kind, model);
    std::printf("  pressure drop        dp            = %.6g Pa (%.4g bar)\n", result.dp,
                result.dp * 1e-5);
    std::printf("  viscous part         dp_viscous    = %.6g Pa\n", result.dp_viscous);
    std::printf("  yield part           dp_yield      = %.6g Pa\n", result.dp_yield);
    std::printf("  plug fraction        delta         = %.6g%s\n", result.plug_fraction,
                o.kind == GapKind::radial ? " (at the mean radius)" : "");
    std::printf("  Bingham number       Bi            = %.6g%s\n", result.bingham_number,
                o.kind == GapKind::radial ? " (at the mean radius)" : "");
  }
}

const bool registered = rheomag::app::register_command([](CLI::App& root) {
  auto options = std::make_shared<FlowOptions>();
  CLI::App* cmd = root.add_subcommand(
      "flow",
      "Pressure drop of one MR-fluid gap (Bingham plastic) at a given yield stress and flow.\n"
      "All values SI. annular: axial flow through an annulus of radial clearance --gap about\n"
      "the mean radius --radius, over --length. radial: flow through a disk gap of axial\n"
      "clearance --gap between --r-in and --r-out.\n"
      "Models: exact = exact Bingham solution (annulus with curvature: plug position solved\n"
      "numerically; radial: local exact slit law integrated along r). approx = paper 000\n"
      "eqs. (2)-(3), c = 2.07 + 12 Q eta / (12 Q eta + 0.8 pi R d^2 tau_y) (radial: the same\n"
      "c(Bi) used locally). Output: dp (total), dp_viscous = Newtonian (tau_y = 0) Poiseuille\n"
      "dp at the same Q, dp_yield = dp - dp_viscous, plug_fraction delta = plug thickness/gap\n"
      "and bingham_number Bi = tau_y h / (mu V_mean) (radial: both at the mean radius;\n"
      "approx: delta is the exact slit value at that Bi). See docs/fluid.md.");
  cmd->add_option_function<std::string>(
         "--kind",
         [options](const std::string& kind) {
           options->kind = kind == "radial" ? GapKind::radial : GapKind::annular;
         },
         "Gap kind: annular or radial")
      ->required()
      ->check(CLI::IsMember({"annular", "radial"}));
  cmd->add_option("--gap", options->gap, "Gap clearance h [m]")->required();
  cmd->add_option("--length", options->length, "annular: active length L [m]");
  cmd->add_option("--radius", options->radius, "annular: mean radius R of the gap [m]");
  cmd->add_option("--r-in", options->r_in, "radial: inner radius [m]");
  cmd->add_option("--r-out", options->r_out, "radial: outer radius [m]");
  cmd->add_option("--tau-y", options->tau_y, "Yield stress tau_y [Pa] (>= 0)")->required();
  cmd->add_option("--viscosity", options->viscosity, "Plastic viscosity mu [Pa s]")->required();
  cmd->add_option("--flow", options->flow, "Volume flow rate Q [m^3/s]")->required();
  cmd->add_option_function<std::string>(
         "--model",
         [options](const std::string& model) {
           options->model = model == "approx" ? FlowModel::approx : FlowModel::exact;
         },
         "exact (default) or approx (paper 000 eqs. 2-3)")
      ->check(CLI::IsMember({"exact", "approx"}));
  cmd->add_flag("--json", options->json, "Print one JSON object to stdout");
  cmd->callback([cmd, options] { run_flow(*cmd, *options); });
});

}  // namespace
