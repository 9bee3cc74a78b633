#pragma once
// Internal to rheomag_case: a FEMM block property as the Material FEMM's magnetostatic solver
// uses.

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "case/femm_file.hpp"
#include "case/problem.hpp"

namespace rheomag::cases::femm {

/// Relative permeabilities along x (r) and y (z) of a linear FEMM block, as FEMM's planar solver
/// makes them (xfemm static2d.cpp): LamType 0 f mu + 1 - f per axis; LamType 1 (laminated along
/// x) f mu_x + 1 - f along x and mu_x / (f + mu_x (1 - f)) across; LamType 2 the same with y and
/// Mu_y. `fail` is called with the reason on a non-positive or non-finite permeability it uses.
std::array<double, 2> linear_femm_permeability(int lam_type, double fill, double mu_x, double mu_y,
                                               const std::function<void(const std::string&)>& fail);

/// What FEMM's axisymmetric solver (xfemm 35baec4, staticaxi.cpp) makes differently of a linear
/// block laminated at LamFill f < 1, where rheomag keeps the planar solver's and the manual's
/// rule: LamType 2 is laminated along r there, as LamType 1; LamType 0 takes mu_r = f Mu, not
/// f Mu + 1 - f (said only when the two differ by more than 0.1 %). A note naming `where`, the
/// block and both values, or "" when FEMM agrees.
std::string axisymmetric_lamination_note(const FemBlock& block, const std::string& where);

/// The material of one FEMM block as FEMM's magnetostatic solver uses it: lamination fill of
/// in-plane laminations folded into mu_r or the B-H curve (smoothed as FEMM does where its spline
/// turns back; a note is added to `warnings`), wire types (LamType >= 3) as mu_r = 1, linear and
/// nonlinear magnets with H_c, linear anisotropic blocks (Mu_x != Mu_y, LamType 1 or 2 with
/// LamFill < 1) with `mu_r_axes`; every other combination refused by name.
Material femm_material(const FemBlock& block, const std::string& source, const FemReader& reader,
                       std::vector<std::string>& warnings);

}  // namespace rheomag::cases::femm
