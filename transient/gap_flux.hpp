#pragma once
// Mean flux density over the fluid-gap regions of a nodal A (the transient's per-step output).

#include <Eigen/Core>
#include <vector>

#include "magnetostatics/solver.hpp"

namespace rheomag::transient {

/// Regions marked as fluid gaps (RegionSeed::gap != none), in region order.
std::vector<int> gap_regions(const magnetostatics::MagnetostaticSolver& statics);

/// Area-weighted mean |B| [T] over each of `regions` for nodal A `a` (quadrature points of the
/// solver's elements, the same rule as the static results' gap averages).
std::vector<double> region_mean_b(const magnetostatics::MagnetostaticSolver& statics,
                                  const std::vector<int>& regions, const Eigen::VectorXd& a);

/// The same mean |B| and its derivative along nodal `da`: d/ds of the mean |B| of a + s da at
/// s = 0+ (e.g. da = dA/dI gives d|B|/dI [T/A]). Where B = 0 the derivative is taken in the
/// direction of the field of nodal `zero_direction` (the one-sided derivative of |B| when the
/// field grows along it, e.g. dA/dI at I = 0). All vectors are nodal.
struct MeanBSlope {
  std::vector<double> b;      ///< area-weighted mean |B| per region [T]
  std::vector<double> slope;  ///< its derivative along da [T per unit of s]
};
MeanBSlope region_mean_b_slope(const magnetostatics::MagnetostaticSolver& statics,
                               const std::vector<int>& regions, const Eigen::VectorXd& a,
                               const Eigen::VectorXd& da, const Eigen::VectorXd& zero_direction);

}  // namespace rheomag::transient
