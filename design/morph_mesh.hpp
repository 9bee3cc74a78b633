#pragma once
// Fixed-topology mesh morphing for rectangle-built geometries: node coordinates are mapped
// piecewise-linearly between the sorted r- and z-breakpoints of the geometry, so a design change
// moves the mesh smoothly instead of re-meshing it (smooth objectives for gradient methods).

#include <optional>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/pslg.hpp"

namespace rheomag::design {

/// Sorted distinct r and z coordinates of a geometry's points [m].
struct Breakpoints {
  std::vector<double> r, z;
};

/// The breakpoints of a PSLG (coordinates closer than 1e-9 m merged).
Breakpoints geometry_breakpoints(const mesh::Pslg& pslg);

/// Moves the nodes of `mesh` (made for breakpoints `from`) so that each coordinate follows the
/// two breakpoints bracketing it to their places in `to`; beyond the outermost breakpoints the
/// map runs linearly to the mesh's own extent, which stays fixed (the far outer boundary).
/// P2 mid-edge nodes are put at the middle of their mapped edge (straight elements).
/// Returns nothing when the breakpoint counts differ, `to` does not fit in the mesh's extent or
/// an element would be inverted or degenerate (signed area <= 0): the caller re-meshes then.
std::optional<mesh::Mesh> morph_mesh(const mesh::Mesh& mesh, const Breakpoints& from,
                                     const Breakpoints& to);

}  // namespace rheomag::design
