#pragma once
// Bingham flow through a radial (disk) gap: the local Bingham number varies with r, so the
// pressure gradient is integrated along r.

#include <functional>

#include "fluid/gap.hpp"

namespace rheomag::fluid {

/// Local slit law used inside a gap whose Bingham number varies along the flow.
enum class SlitLaw {
  exact,     ///< c = 3 - delta^2 from the plug-fraction cubic
  paper000,  ///< c = 2.07 + 12 / (12 + 0.4 Bi) (paper 000, eq. 3)
};

/// Radial gap with a uniform yield stress tau_y [Pa].
GapPressureDrop radial_bingham(const RadialGeometry& g, double tau_y, double viscosity, double flow,
                               SlitLaw law = SlitLaw::exact);

/// Radial gap with a yield stress tau_y(r) [Pa] varying with radius r [m]; the yield part of
/// dp = int (6 mu Q / (pi r h^3) + c(Bi(r)) tau_y(r) / h) dr is integrated by adaptive
/// Gauss-Kronrod quadrature (relative tolerance 1e-10).
GapPressureDrop radial_bingham(const RadialGeometry& g,
                               const std::function<double(double)>& tau_y_of_r, double viscosity,
                               double flow, SlitLaw law = SlitLaw::exact);

}  // namespace rheomag::fluid
