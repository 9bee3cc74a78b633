#pragma once
// Triangular mesh of the meridian plane: linear (3-node) or quadratic (6-node) triangles.

#include <array>
#include <vector>

#include "mesh/pslg.hpp"

namespace rheomag::mesh {

/// A boundary edge of the mesh carrying a boundary-condition marker (from Segment::boundary).
struct BoundaryEdge {
  std::array<int, 3> nodes{-1, -1, -1};  ///< end nodes, then the midpoint node for P2 (else -1)
  int boundary = -1;
};

/// Triangle mesh. Node numbering: the vertices first, then (order 2) one node per edge midpoint.
/// Triangle node order: v0, v1, v2 counter-clockwise, then midpoints of (v0v1), (v1v2), (v2v0).
struct Mesh {
  int order = 1;
  std::vector<Point> nodes;
  std::vector<std::array<int, 6>> triangles;  ///< for order 1 only the first three are used
  std::vector<int> region;                    ///< region index (into Pslg::regions) per triangle
  std::vector<BoundaryEdge> boundary_edges;   ///< constrained edges carrying a marker
  int vertex_count = 0;                       ///< nodes [0, vertex_count) are triangle vertices

  /// Number of nodes per triangle (3 or 6).
  int nodes_per_triangle() const { return order == 1 ? 3 : 6; }
};

}  // namespace rheomag::mesh
