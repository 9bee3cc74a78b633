#pragma once
// Newtonian (unmagnetised) laminar passages and minor losses, SI units.

#include "fluid/gap.hpp"

namespace rheomag::fluid {

/// Plane Poiseuille: dp = 12 mu Q L / (b h^3).
double slit_poiseuille_dp(const SlitGeometry& g, double viscosity, double flow);

/// Exact laminar annulus (Bird, Stewart & Lightfoot, Transport Phenomena, eq. 2.4-17), evaluated
/// without cancellation for thin gaps.
double annulus_poiseuille_dp(const AnnulusGeometry& g, double viscosity, double flow);

/// Hagen-Poiseuille pipe: dp = 128 mu Q L / (pi D^4).
double pipe_poiseuille_dp(double diameter, double length, double viscosity, double flow);

/// Radial (disk) Poiseuille between r_in and r_out: dp = 6 mu Q ln(r_out/r_in) / (pi h^3).
double radial_poiseuille_dp(const RadialGeometry& g, double viscosity, double flow);

/// Entrance/exit/bend (minor) loss dp = K rho V^2 / 2 with V = Q / area.
double minor_loss_dp(double loss_coefficient, double density, double flow, double area);

/// Reynolds number rho V D_h / mu with V = Q / area (laminar formulas assume Re < ~2000).
double reynolds_number(double density, double viscosity, double flow, double area,
                       double hydraulic_diameter);

/// atanh(x) - x for 0 <= x < 1 without cancellation at small x.
double atanh_minus_x(double x);

}  // namespace rheomag::fluid
