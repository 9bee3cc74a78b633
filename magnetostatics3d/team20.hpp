#pragma once
// TEAM workshop problem 20 (3-D static force problem): a steel yoke and centre pole magnetised by
// a rectangular coil with rounded corners; the measured force on the pole is the reference.

#include "magnetostatics/newton.hpp"
#include "magnetostatics3d/band_coil.hpp"
#include "magnetostatics3d/grid_mesh.hpp"

namespace rheomag::magnetostatics3d {

/// Mesh settings of the TEAM 20 quarter model.
struct Team20Options {
  double step = 2.5e-3;  ///< cell size in and near the pole [m]; the rest graded from it
  magnetostatics::NewtonOptions newton;
};

/// One solve of TEAM 20 at a coil excitation.
struct Team20Result {
  double ampere_turns = 0.0;
  double force_z = 0.0;        ///< z force on the whole centre pole [N] (virtual work)
  double flux_linkage = 0.0;   ///< of the 1000-turn coil, whole model [Wb]
  double pole_mean_bz = 0.0;   ///< mean B_z over the pole's volume [T]
  std::size_t tetrahedra = 0;  ///< of the quarter model
  int dofs = 0;                ///< cotree unknowns of the quarter model
  int newton_iterations = 0;
  double seconds = 0.0;
};

/// The TEAM 20 coil (1000 turns; 75 x 75 mm outside with 23 mm corner radius, 18 mm wide,
/// 96.6 mm high from z = 26.7 mm). Dimensions of the problem's definition (Takahashi, Nakata,
/// Morishige, COMPEL 14(2/3) 57-75, 1995; docs/magnetostatics3d.md).
BandCoil team20_coil();

/// The quarter model x >= 0, y >= 0 (B tangent to both symmetry planes, tangential A = 0 on
/// them and on the far box) on a graded grid: regions 0 air, 1 yoke, 2 pole.
GridSpec team20_grid(const Team20Options& options);

/// Solves TEAM 20 at the given coil excitations [ampere-turns] (nonlinear steel of the
/// problem's B-H table) on one mesh. Throws ConvergenceError if Newton fails.
std::vector<Team20Result> solve_team20(const std::vector<double>& ampere_turns,
                                       const Team20Options& options = {});

}  // namespace rheomag::magnetostatics3d
