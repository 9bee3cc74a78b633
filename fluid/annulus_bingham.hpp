#pragma once
// Exact axial Bingham flow (Poiseuille-Bingham) in a concentric annulus with curvature.

#include "fluid/gap.hpp"

namespace rheomag::fluid {

/// Where the plug sits in an annulus at one pressure gradient.
struct AnnulusPlug {
  double inner = 0.0;     ///< plug inner radius r1 [m]
  double outer = 0.0;     ///< plug outer radius r2 = r1 + 2 tau_y / G [m]
  double gradient = 0.0;  ///< pressure gradient G = -dp/dz [Pa/m]
  double flow = 0.0;      ///< volume flow rate at that gradient [m^3/s]
};

/// The plug and flow rate of an annulus whose plug fills `plug_fraction` (0, 1] of the gap.
AnnulusPlug annulus_plug(const AnnulusGeometry& g, double tau_y, double viscosity,
                         double plug_fraction);

/// Exact Bingham annulus at flow rate Q: the plug position and pressure gradient are solved
/// numerically; dp_viscous is the exact Newtonian annulus value.
GapPressureDrop annulus_bingham(const AnnulusGeometry& g, double tau_y, double viscosity,
                                double flow);

}  // namespace rheomag::fluid
