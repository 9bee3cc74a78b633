#include "magnetostatics3d/gauge.hpp"

#include <numeric>
#include <queue>

#include "core/error.hpp"

namespace rheomag::magnetostatics3d {
namespace {

/// Disjoint sets of nodes (union by size, path halving).
class NodeSets {
 public:
  explicit NodeSets(int n) : parent_(n), size_(n, 1) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int find(int x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  bool unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    return true;
  }

 private:
  std::vector<int> parent_, size_;
};

/// The edges of the mesh's condition faces, marked in d.fixed (d.dof_of_edge all -1); `on_face`
/// is called with each node of those faces.
template <typename OnFaceNode>
EdgeDofs condition_edges(const TetMesh& mesh, OnFaceNode on_face) {
  if (mesh.faces.empty()) {
    throw InputError("3D mesh: no outer or symmetry boundary, so A is not determined");
  }
  EdgeDofs d;
  const int n_edges = static_cast<int>(mesh.edges.size());
  d.fixed.assign(n_edges, false);
  d.dof_of_edge.assign(n_edges, -1);
  // Edge lookup through the edges of each node.
  std::vector<std::vector<std::pair<int, int>>> by_node(mesh.nodes.size());  // (other, edge)
  for (int e = 0; e < n_edges; ++e) by_node[mesh.edges[e][0]].push_back({mesh.edges[e][1], e});
  auto find_edge = [&](int a, int b) {
    if (a > b) std::swap(a, b);
    for (const auto& [other, e] : by_node[a])
      if (other == b) return e;
    return -1;
  };
  for (const auto& f : mesh.faces) {
    for (int k = 0; k < 3; ++k) {
      const int e = find_edge(f[k], f[(k + 1) % 3]);
      if (e >= 0) d.fixed[e] = true;
      on_face(f[k]);
    }
  }
  return d;
}

}  // namespace

EdgeDofs tree_cotree_dofs(const TetMesh& mesh) {
  // The spanning tree is grown from all fixed-edge nodes taken as one node.
  NodeSets sets(static_cast<int>(mesh.nodes.size()));
  const int anchor = mesh.faces.empty() ? 0 : mesh.faces.front()[0];
  EdgeDofs d = condition_edges(mesh, [&](int node) { sets.unite(anchor, node); });
  for (int e = 0; e < static_cast<int>(mesh.edges.size()); ++e) {
    if (d.fixed[e]) continue;
    if (sets.unite(mesh.edges[e][0], mesh.edges[e][1])) {
      ++d.tree_edges;
    } else {
      d.dof_of_edge[e] = d.free_count();
      d.edge_of_dof.push_back(e);
    }
  }
  return d;
}

EdgeDofs free_edge_dofs(const TetMesh& mesh) {
  EdgeDofs d = condition_edges(mesh, [](int) {});
  for (int e = 0; e < static_cast<int>(mesh.edges.size()); ++e) {
    if (d.fixed[e]) continue;
    d.dof_of_edge[e] = d.free_count();
    d.edge_of_dof.push_back(e);
  }
  return d;
}

Eigen::VectorXd cotree_values(const TetMesh& mesh, const EdgeDofs& dofs, const Eigen::VectorXd& a) {
  // Potential phi per node: 0 on the fixed edges' nodes, grown along the tree edges (a breadth-
  // first walk over the spanning tree of tree_cotree_dofs) so that phi_b - phi_a = a_e on each.
  const int n_nodes = static_cast<int>(mesh.nodes.size());
  std::vector<std::vector<int>> tree_edges_of(n_nodes);
  std::vector<double> phi(n_nodes, 0.0);
  std::vector<bool> known(n_nodes, false);
  std::queue<int> front;
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const auto& [p, q] = mesh.edges[e];
    if (dofs.fixed[e]) {
      for (int node : {p, q}) {
        if (!known[node]) front.push(node);
        known[node] = true;
      }
    } else if (dofs.dof_of_edge[e] < 0) {
      tree_edges_of[p].push_back(static_cast<int>(e));
      tree_edges_of[q].push_back(static_cast<int>(e));
    }
  }
  for (; !front.empty(); front.pop()) {
    const int node = front.front();
    for (int e : tree_edges_of[node]) {
      const auto& [p, q] = mesh.edges[e];
      const int other = p == node ? q : p;
      if (known[other]) continue;
      phi[other] = phi[node] + (other == q ? a[e] : -a[e]);
      known[other] = true;
      front.push(other);
    }
  }
  Eigen::VectorXd x(dofs.free_count());
  for (int d = 0; d < dofs.free_count(); ++d) {
    const int e = dofs.edge_of_dof[d];
    x[d] = a[e] - (phi[mesh.edges[e][1]] - phi[mesh.edges[e][0]]);
  }
  return x;
}

}  // namespace rheomag::magnetostatics3d
