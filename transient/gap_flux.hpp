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

}  // namespace rheomag::transient
