#pragma once
// The paper 001 bypass rig the lumped tests share: piston 452.4 mm^2, Bingham map 0-5.8 MPa over
// 0-1 A, viscous resistance 1.5e10 Pa s/m^3, plug regularised at 1e-9 m^3/s.

#include "lumped/rig_model.hpp"

namespace rheomag::test {

/// The bypass rig of paper 001 with a stiff fluid (no optional effect switched on).
inline lumped::RigSpec bypass_rig() {
  lumped::RigSpec s;
  s.kind = lumped::RigKind::bypass_cylinder;
  s.piston_area = 4.524e-4;
  s.valve.yield_current = {0.0, 1.0};
  s.valve.yield_pressure = {0.0, 5.8e6};
  s.valve.viscous_resistance = 1.5e10;
  s.valve.regularisation_flow = 1e-9;
  return s;
}

}  // namespace rheomag::test
