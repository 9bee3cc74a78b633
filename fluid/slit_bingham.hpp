#pragma once
// Exact Bingham-plastic flow through a slit (and a thin annulus treated as a slit of width
// 2 pi R), and the paper-000 approximation of the velocity-profile coefficient.

#include "fluid/gap.hpp"

namespace rheomag::fluid {

/// Bingham number Bi = tau_y h / (mu V), V = Q / (b h), of a slit of gap h and width b.
double bingham_number(double tau_y, double viscosity, double gap, double width, double flow);

/// Plug fraction delta in [0, 1]: the root of delta^3 - 3 (1 + 4/Bi) delta + 2 = 0.
double slit_plug_fraction(double bingham_number);

/// Exact velocity-profile coefficient c = 2/delta - 12/Bi = 3 - delta^2 (3 at Bi=0, 2 at Bi=inf).
double slit_yield_coefficient(double bingham_number);

/// Paper-000 eq. (3) written with Bi: c = 2.07 + 12 / (12 + 0.4 Bi).
double paper000_yield_coefficient(double bingham_number);

/// Exact Bingham slit: dp = 12 mu Q L / (b h^3) + c tau_y L / h.
GapPressureDrop slit_bingham(const SlitGeometry& g, double tau_y, double viscosity, double flow);

/// Annulus as a slit of width 2 pi R (the thin-gap limit of annulus_bingham).
GapPressureDrop annulus_slit_bingham(const AnnulusGeometry& g, double tau_y, double viscosity,
                                     double flow);

/// Paper-000 eqs. (2)-(3): dp = 6 eta Q L / (pi d^3 R) + c tau_y L / d; plug_fraction reports the
/// exact slit delta at the same Bi (the approximation itself has none).
GapPressureDrop annulus_paper000(const AnnulusGeometry& g, double tau_y, double viscosity,
                                 double flow);

}  // namespace rheomag::fluid
