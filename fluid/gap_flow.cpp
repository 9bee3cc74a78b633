#include "fluid/gap_flow.hpp"

#include "core/error.hpp"
#include "core/format_text.hpp"
#include "fluid/radial_bingham.hpp"
#include "fluid/slit_bingham.hpp"

namespace rheomag::fluid {

GapFlowResult gap_flow(const GapFlowInput& o) {
  const bool moving = o.wall_velocity != 0.0;
  if (o.model == FlowModel::approx &&
      (moving || o.flow_index != 1.0 || o.kind == FlowGapKind::slit))
    throw InputError(
        "--model approx (paper 000) is for a still-walled Bingham annular or radial gap only");
  if (o.kind == FlowGapKind::radial && (moving || o.flow_index != 1.0))
    throw InputError("--wall-velocity and --flow-index apply to --kind annular and slit only");
  const GapRheology fluid{o.tau_y, o.viscosity, o.flow_index};
  GapFlowResult result;
  result.input = o;
  if (o.kind == FlowGapKind::radial) {
    const RadialGeometry g{o.gap, o.r_in, o.r_out};
    result.drop = radial_bingham(g, o.tau_y, o.viscosity, o.flow,
                                 o.model == FlowModel::exact ? SlitLaw::exact : SlitLaw::paper000);
  } else if (o.model == FlowModel::approx) {
    result.drop =
        annulus_paper000(AnnulusGeometry{o.gap, o.radius, o.length}, o.tau_y, o.viscosity, o.flow);
  } else {
    result.mixed = o.kind == FlowGapKind::annular
                       ? annulus_mixed_mode(AnnulusGeometry{o.gap, o.radius, o.length}, fluid,
                                            o.wall_velocity, o.flow)
                       : slit_mixed_mode(SlitGeometry{o.gap, o.width, o.length}, fluid,
                                         o.wall_velocity, o.flow);
    result.drop = result.mixed->drop;
  }
  result.regime = result.mixed ? std::string(kMixedRegimeNames.name(result.mixed->regime))
                               : std::string(o.tau_y > 0.0 ? "floating_plug" : "fully_yielded");
  return result;
}

nlohmann::json gap_flow_json(const GapFlowResult& result) {
  const GapPressureDrop& d = result.drop;
  nlohmann::json out = {{"kind", std::string(kFlowGapKindNames.name(result.input.kind))},
                        {"model", std::string(kFlowModelNames.name(result.input.model))},
                        {"wall_velocity", result.input.wall_velocity},
                        {"regime", result.regime},
                        {"dp", d.dp},
                        {"dp_yield", d.dp_yield},
                        {"dp_viscous", d.dp_viscous},
                        {"plug_fraction", d.plug_fraction},
                        {"bingham_number", d.bingham_number}};
  if (result.mixed) {
    out["plug_start"] = result.mixed->plug_start;
    out["plug_end"] = result.mixed->plug_end;
    out["moving_wall_stress"] = result.mixed->moving_wall_stress;
    out["fixed_wall_stress"] = result.mixed->fixed_wall_stress;
    out["moving_wall_force"] = result.mixed->moving_wall_force;
  }
  return out;
}

std::string gap_flow_text(const GapFlowResult& result) {
  const GapPressureDrop& d = result.drop;
  const char* at_mean = result.input.kind == FlowGapKind::radial ? " (at the mean radius)" : "";
  std::string out = format_text("%s gap, %s model, wall velocity %g m/s\n",
                                std::string(kFlowGapKindNames.name(result.input.kind)).c_str(),
                                std::string(kFlowModelNames.name(result.input.model)).c_str(),
                                result.input.wall_velocity);
  out +=
      format_text("  pressure drop        dp            = %.6g Pa (%.4g bar)\n", d.dp, d.dp * 1e-5);
  out += format_text("  viscous part         dp_viscous    = %.6g Pa\n", d.dp_viscous);
  out += format_text("  yield part           dp_yield      = %.6g Pa\n", d.dp_yield);
  out +=
      format_text("  regime                               %s%s\n", result.regime.c_str(), at_mean);
  out += format_text("  plug fraction        delta         = %.6g%s\n", d.plug_fraction, at_mean);
  out += format_text("  Bingham number       Bi            = %.6g%s\n", d.bingham_number, at_mean);
  if (result.mixed) {
    out += format_text("  plug                 from %.6g to %.6g m off the moving wall\n",
                       result.mixed->plug_start, result.mixed->plug_end);
    out += format_text("  moving-wall force    F_wall        = %.6g N (shear stress %.6g Pa)\n",
                       result.mixed->moving_wall_force, result.mixed->moving_wall_stress);
  }
  return out;
}

}  // namespace rheomag::fluid
