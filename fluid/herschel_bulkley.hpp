#pragma once
// Herschel-Bulkley (tau = tau_y + K gamma_dot^n) flow through a slit; n = 1 is Bingham.

#include "fluid/gap.hpp"

namespace rheomag::fluid {

/// Flow rate [m^3/s] through a slit at wall shear stress tau_w [Pa] (0 if tau_w <= tau_y).
double herschel_bulkley_slit_flow(const SlitGeometry& g, double tau_y, double consistency,
                                  double flow_index, double wall_stress);

/// Herschel-Bulkley slit at flow rate Q: the wall stress is solved numerically. dp_viscous is
/// the power-law (tau_y = 0) value, plug_fraction = tau_y / tau_w, and bingham_number is
/// tau_y / (K (V/h)^n).
GapPressureDrop herschel_bulkley_slit(const SlitGeometry& g, double tau_y, double consistency,
                                      double flow_index, double flow);

}  // namespace rheomag::fluid
