#pragma once
// Internal to rheomag_mesh: the pieces of a cut segment joined back into one straight run, so
// that the size field holds one source per run instead of one per piece.

#include <array>
#include <vector>

namespace rheomag::mesh::detail {

/// A straight edge that sets a target element size near it: its ends (r, z) [m] and size [m].
struct SizedEdge {
  std::array<double, 2> a, b;
  double size;
};

/// The edges joined into maximal straight runs: two edges are joined where they have the same
/// size, share an end that no third edge touches, and continue one another in a straight line
/// (to 1e-9 of their lengths). Every point's distance to a run is its distance to the nearest
/// of the run's edges, so a size field over the runs equals the one over the edges.
std::vector<SizedEdge> merge_straight_runs(const std::vector<SizedEdge>& edges);

}  // namespace rheomag::mesh::detail
