#pragma once
// Linear to quadratic triangles: one extra node at the midpoint of every edge.

#include "mesh/mesh.hpp"

namespace rheomag::mesh {

/// Returns the 6-node version of a linear mesh: node numbering, triangle midpoint order and
/// BoundaryEdge::nodes[2] as documented in mesh.hpp. A mesh already of order 2 is returned as is.
Mesh elevate_to_p2(const Mesh& linear);

}  // namespace rheomag::mesh
