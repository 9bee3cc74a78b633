#pragma once
// Exact mixed-mode (pressure- plus wall-driven) Bingham / Herschel-Bulkley flow in a slit or an
// annulus whose inner (moving) wall slides along the flow direction: the gap of a piston head.

#include "core/enum_names.hpp"
#include "fluid/gap.hpp"

namespace rheomag::fluid {

/// Where the unyielded fluid sits in a gap with one moving wall.
enum class MixedRegime {
  fully_yielded,        ///< no plug in the gap (the stress never enters [-tau_y, tau_y])
  plug_on_moving_wall,  ///< a plug stuck to the moving wall, moving with it
  plug_on_fixed_wall,   ///< a plug stuck to the fixed wall, at rest
  floating_plug,        ///< a plug between two yielded layers
  unyielded,            ///< the whole gap rigid (only with a still wall and no flow)
};

/// Text form of MixedRegime for JSON and messages.
inline constexpr auto kMixedRegimeNames = enum_names<MixedRegime>({
    {MixedRegime::fully_yielded, "fully_yielded"},
    {MixedRegime::plug_on_moving_wall, "plug_on_moving_wall"},
    {MixedRegime::plug_on_fixed_wall, "plug_on_fixed_wall"},
    {MixedRegime::floating_plug, "floating_plug"},
    {MixedRegime::unyielded, "unyielded"},
});

/// Herschel-Bulkley law tau = tau_y + K gamma_dot^n of the fluid in one gap (Bingham: n = 1).
struct GapRheology {
  double tau_y = 0.0;        ///< yield stress [Pa]
  double consistency = 0.0;  ///< plastic viscosity (n = 1) or consistency K [Pa s^n]
  double flow_index = 1.0;   ///< n
};

/// Mixed-mode result: the pressure drop with the regime and where the plug is.
struct MixedModeDrop {
  GapPressureDrop drop;      ///< dp (may be < 0), dp_viscous at tau_y = 0, plug fraction, Bi
  double wall_velocity = 0;  ///< U of the moving wall along the flow [m/s]
  MixedRegime regime = MixedRegime::fully_yielded;
  double plug_start = 0.0;  ///< plug edge nearer the moving wall, distance from it [m]
  double plug_end = 0.0;    ///< plug edge nearer the fixed wall, distance from the moving wall [m]
  double moving_wall_stress = 0.0;  ///< shear stress tau_xy at the moving wall [Pa]
  double fixed_wall_stress = 0.0;   ///< shear stress at the fixed wall [Pa]
  double moving_wall_force = 0.0;   ///< shear force of the fluid on the moving wall, along the
                                    ///< flow [N] (stress times wall area b L or 2 pi R_in L)
};

/// Slit of gap h, width b, length L; the wall at y = 0 moves at `wall_velocity` along the flow,
/// the wall at y = h is fixed; `flow` [m^3/s] is counted in the fixed wall's frame. Returns the
/// pressure drop dp (upstream minus downstream) that carries `flow`.
MixedModeDrop slit_mixed_mode(const SlitGeometry& g, const GapRheology& fluid, double wall_velocity,
                              double flow);

/// Annulus (mean radius R, clearance h, length L) whose inner wall moves at `wall_velocity`
/// along the flow and outer wall is fixed; `flow` in the outer wall's frame.
MixedModeDrop annulus_mixed_mode(const AnnulusGeometry& g, const GapRheology& fluid,
                                 double wall_velocity, double flow);

/// The forward problem: flow rate [m^3/s] through the slit at pressure drop dp [Pa].
double slit_mixed_mode_flow(const SlitGeometry& g, const GapRheology& fluid, double wall_velocity,
                            double dp);

/// The forward problem: flow rate [m^3/s] through the annulus at pressure drop dp [Pa].
double annulus_mixed_mode_flow(const AnnulusGeometry& g, const GapRheology& fluid,
                               double wall_velocity, double dp);

}  // namespace rheomag::fluid
