#pragma once
// Force and torque on a body by the weighted Maxwell stress tensor (FEMM's mo_blockintegral 18,
// 19 and 22): the stress tensor of the media around the body (air, as in FEMM, or an MR fluid),
// weighted by the gradient of a mask that is 1 on the body and 0 on the solids around it and on
// the outer boundary.

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
  /// Mesh nodes where the body meets an interface between two media (air and a fluid, two
  /// fluids): the mask must move them with the body and keep the interface still, so the result
  /// carries an error of the order of the element size there.
  std::vector<mesh::Point> junctions;
  double junction_size = 0.0;  ///< longest edge of the triangles at the junctions [m]
};

/// True when region `region` is free space for the mask: mu_r = 1, no B-H curve, no magnet, no
/// fixed current density, no coil.
bool is_air_region(const cases::Problem& problem, int region);

/// Mask w at every mesh node: 1 on the nodes of the selected regions; 0 on the outer boundary
/// (not on the axis of an axisymmetric problem), on every solid region (neither free space nor
/// a source-free fluid: steel, coils, magnets, fixed J) and on the interfaces between two media
/// (free space and a fluid, or two fluids) away from the body; harmonic (Laplace's equation in
/// the plane, same element order as the mesh) in the media. With free space only this is FEMM's
/// mask. InputError naming both regions when a selected region touches an unselected solid (no
/// layer for the stress tensor) and when nothing is selected.
/// `junctions`, when given, receives the nodes where the body meets an interface of two media.
Eigen::VectorXd stress_tensor_mask(const MagnetostaticSolver& solver,
                                   const std::vector<int>& selected,
                                   std::vector<int>* junctions = nullptr);

/// F_i = -integral T_ij dw/dx_j dV over the medium, T_ij = H_i B_j - delta_ij w'(B) with w' the
/// co-energy density (nu0 (B_i B_j - delta_ij |B|^2 / 2) in free space), and (planar) the torque
/// -integral (x (T grad w)_y - y (T grad w)_x) dV. This is the virtual work at constant current
/// of the displacement w (Coulomb's method), exact for any mask: in free space it is the
/// stress-tensor surface integral averaged over the mask's level sets.
StressTensorForce stress_tensor_force(const MagnetostaticSolver& solver, const Solution& solution,
                                      const std::vector<int>& selected);

}  // namespace rheomag::magnetostatics
