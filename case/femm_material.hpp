#pragma once
// Internal to rheomag_case: a FEMM block property as the Material FEMM's magnetostatic solver
// uses.

#include <string>
#include <vector>

#include "case/femm_file.hpp"
#include "case/problem.hpp"

namespace rheomag::cases::femm {

/// The material of one FEMM block as FEMM's magnetostatic solver uses it: lamination fill of
/// in-plane laminations folded into mu_r or the B-H curve (smoothed as FEMM does where its spline
/// turns back; a note is added to `warnings`), wire types (LamType >= 3) as mu_r = 1, linear and
/// nonlinear magnets with H_c; every other combination refused by name.
Material femm_material(const FemBlock& block, const std::string& source, const FemReader& reader,
                       std::vector<std::string>& warnings);

}  // namespace rheomag::cases::femm
