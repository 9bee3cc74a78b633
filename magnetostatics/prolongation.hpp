#pragma once
// Interpolation of a nodal field from one mesh of a geometry to another mesh of the same geometry
// (the prolongation of nested iteration: a coarse solution as the start of a fine solve).

#include <Eigen/Core>

#include "mesh/mesh.hpp"

namespace rheomag::magnetostatics {

/// The P1/P2 field `values` (one per node of `from`) evaluated at every node of `to`. Each node is
/// located in a triangle of `from` through a bucket grid; a node outside `from` (a curved boundary
/// meshed differently) takes the value at the nearest point of the closest triangle found.
Eigen::VectorXd interpolate_nodal(const mesh::Mesh& from, const Eigen::VectorXd& values,
                                  const mesh::Mesh& to);

}  // namespace rheomag::magnetostatics
