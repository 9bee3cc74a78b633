#pragma once
// `rheomag flow` as a library call: the pressure drop of one gap (annular, slit or radial) at a
// yield stress and flow rate, optionally with the inner wall moving, with the law chosen from
// the gap kind and model; and that result as a JSON document and as a text report.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/enum_names.hpp"
#include "fluid/gap.hpp"
#include "fluid/mixed_mode.hpp"

namespace rheomag::fluid {

/// The shape of the one gap of `rheomag flow`.
enum class FlowGapKind { annular, slit, radial };

/// Which law: the exact solution, or paper 000's approximation (still-walled Bingham only).
enum class FlowModel { exact, approx };

/// Text names of FlowGapKind and FlowModel (CLI, JSON).
inline constexpr auto kFlowGapKindNames =
    enum_names<FlowGapKind>({{FlowGapKind::annular, "annular"},
                             {FlowGapKind::slit, "slit"},
                             {FlowGapKind::radial, "radial"}});
inline constexpr auto kFlowModelNames =
    enum_names<FlowModel>({{FlowModel::exact, "exact"}, {FlowModel::approx, "approx"}});

/// One gap and its flow (SI). Only the dimensions of `kind` are read: annular gap, length,
/// radius; slit gap, length, width; radial gap, r_in, r_out.
struct GapFlowInput {
  FlowGapKind kind = FlowGapKind::annular;
  FlowModel model = FlowModel::exact;
  double gap = 0, length = 0, radius = 0, width = 0, r_in = 0, r_out = 0;
  double tau_y = 0, viscosity = 0, flow = 0, wall_velocity = 0, flow_index = 1.0;
};

/// The drop of one gap, plus the mixed-mode details for the exact annular and slit laws.
struct GapFlowResult {
  GapFlowInput input;
  GapPressureDrop drop;
  std::optional<MixedModeDrop> mixed;
  std::string regime;  ///< kMixedRegimeNames, or floating_plug / fully_yielded without `mixed`
};

/// The drop of `input`'s gap. InputError for the approx model with a moving wall, a flow index
/// or a slit, for a radial gap with a moving wall or a flow index, and for bad dimensions.
GapFlowResult gap_flow(const GapFlowInput& input);

/// The JSON document of `rheomag flow --json` (SI units).
nlohmann::json gap_flow_json(const GapFlowResult& result);

/// The text report of `rheomag flow`.
std::string gap_flow_text(const GapFlowResult& result);

}  // namespace rheomag::fluid
