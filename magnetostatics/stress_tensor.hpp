#pragma once
// Force and torque on a body by the weighted Maxwell stress tensor (FEMM's mo_blockintegral 18,
// 19 and 22): the stress tensor of the air around the body, weighted by the gradient of a mask
// that is 1 on the body and 0 on every other non-air region and on the outer boundary.

#include <array>
#include <vector>

#include "magnetostatics/solver.hpp"

namespace rheomag::magnetostatics {

/// Force and torque on the selected regions [N, N m].
struct StressTensorForce {
  /// Planar: (F_x, F_y) per the problem's depth. Axisymmetric: (0, F_z) — the radial resultant
  /// of a body of revolution vanishes.
  std::array<double, 2> force{};
  double torque = 0.0;  ///< planar: about the origin, counter-clockwise positive; axisymmetric 0
};

/// True when region `region` is free space for the mask: mu_r = 1, no B-H curve, no magnet, no
/// fixed current density, no coil.
bool is_air_region(const cases::Problem& problem, int region);

/// Mask w at every mesh node: 1 on the nodes of the selected regions, 0 on those of other
/// non-air regions and on the outer boundary (not on the axis of an axisymmetric problem), and
/// harmonic (Laplace's equation in the plane, same element order as the mesh) in the air
/// between. InputError naming both regions when a selected region touches a non-air one (no air
/// layer for the stress tensor) and when nothing is selected.
Eigen::VectorXd stress_tensor_mask(const MagnetostaticSolver& solver,
                                   const std::vector<int>& selected);

/// F_i = -integral T_ij dw/dx_j dV over the air, T_ij = nu0 (B_i B_j - delta_ij |B|^2 / 2), and
/// (planar) the torque -integral (x (T grad w)_y - y (T grad w)_x) dV. Exact for any mask in the
/// continuum: it is the stress-tensor surface integral averaged over the mask's level sets.
StressTensorForce stress_tensor_force(const MagnetostaticSolver& solver, const Solution& solution,
                                      const std::vector<int>& selected);

}  // namespace rheomag::magnetostatics
