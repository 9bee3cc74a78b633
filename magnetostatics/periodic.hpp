#pragma once
// Periodic and antiperiodic boundaries: each node of a slave edge takes plus or minus the value
// that the master edge's finite-element trace has at the corresponding position.

#include <vector>

#include "case/problem.hpp"
#include "mesh/mesh.hpp"

namespace rheomag::magnetostatics {

/// One term of a linear constraint: weight x (value at node).
struct NodeTerm {
  int node = -1;
  double weight = 0.0;
};

/// Per mesh node: whether it is a slave, and its value as a combination of non-slave nodes.
struct PeriodicConstraints {
  std::vector<bool> slave;                   ///< true: the node's value is given by `terms`
  std::vector<std::vector<NodeTerm>> terms;  ///< A(node) = sum weight x A(term node)
  bool antiperiodic = false;                 ///< some antiperiodic pair is active
  /// True when there is at least one slave node.
  bool any() const;
};

/// Pairs the mesh edges of every (anti)periodic boundary condition with its partner's (the lower
/// condition index is the master). Both edges are followed with the meshed domain on their left
/// and parametrised by normalised arc length; as in FEMM the master's start pairs with the
/// slave's end, and a slave node at parameter t gets +-(the master's P1 or P2 edge interpolant at
/// 1 - t): exact where the nodes match, consistent otherwise. Nodes with `fixed` true
/// keep their prescribed value. A node on two pairs (a corner) is constrained by the first and
/// chains through the second; a node paired with itself is free (periodic) or 0 (antiperiodic).
/// InputError naming the boundary when an edge has no mesh edges, its mesh edges are not one
/// simple path, or the two paths' lengths differ by more than 1e-6 relative.
PeriodicConstraints periodic_constraints(const mesh::Mesh& mesh, const cases::Problem& problem,
                                         const std::vector<bool>& fixed);

}  // namespace rheomag::magnetostatics
