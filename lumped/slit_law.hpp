#pragma once
// The exact slit (Buckingham) law of a Bingham fluid written against the Bingham line a valve
// table states: the same asymptote (intercept p_b, slope R), a plug that yields at 2/3 p_b and a
// curved knee between. fluid/slit_bingham.hpp solves the same law from a gap's geometry.

namespace rheomag::lumped {

/// Plug fraction delta in (0, 1] of a slit at flow ratio rho = R |Q| / p_b >= 0: the root of
/// delta^3 - 3 (1 + rho) delta + 2 = 0 (closed form); the slit's yield part is p_b (1 - delta^2/3).
double slit_plug_at_flow(double flow_ratio);

/// Flow [m^3/s] >= 0 of a valve whose yield part is p_b (1 - k delta^2 / 3) (k in [0, 1]: 0 the
/// Bingham line, 1 the exact slit) at pressure `excess` >= 0 [Pa] above its onset p_b (1 - k / 3):
/// the root Q of R Q + k p_b (1 - delta(Q)^2) / 3 = excess. `intercept` p_b > 0 [Pa],
/// `resistance` R > 0 [Pa s/m^3].
double knee_flow(double excess, double intercept, double resistance, double k);

}  // namespace rheomag::lumped
