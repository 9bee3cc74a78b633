#pragma once
// FEMM 4.2's magnetostatic solution file (.ans) of a solved field: the model as `export` writes
// it, then the [Solution] section as FEMM's solver writes it (xfemm fsolver WriteStatic2D).

#include <string>

#include "magnetostatics/solver.hpp"

namespace rheomag::magnetostatics {

/// The .ans text of `solution` on `solver`'s mesh. Nodes in the file's length unit with A
/// [Wb/m] (planar) or 2 pi r A [Wb] (axisymmetric); quadratic triangles split into four linear
/// ones; each label's circuit current density as FEMM's post-processor reads it. InputError for
/// what a .fem cannot hold (write_femm_for_mesh).
std::string femm_ans_text(const MagnetostaticSolver& solver, const Solution& solution);

}  // namespace rheomag::magnetostatics
