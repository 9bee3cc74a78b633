#include "magnetostatics/periodic.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "core/error.hpp"

namespace rheomag::magnetostatics {
namespace {

/// One mesh edge of a boundary path, oriented along the path, with its end parameters.
struct PathEdge {
  int from = -1, to = -1, mid = -1;  // nodes; mid = -1 for P1
  double t0 = 0.0, t1 = 0.0;         // normalised arc length at from and to
};

/// The mesh edges of boundary condition `marker` as one path, followed with the domain on its left.
struct Path {
  std::vector<PathEdge> edges;
  double length = 0.0;
};

std::string boundary_name(const cases::Problem& problem, int marker) {
  const cases::BoundaryCondition& bc = problem.boundaries[marker];
  return problem.geometry.source + ": " +
         (bc.kind == cases::BoundaryKind::periodic ? "periodic" : "antiperiodic") + " boundary '" +
         bc.name + "'";
}

Path boundary_path(const mesh::Mesh& mesh, const cases::Problem& problem, int marker) {
  std::map<int, std::vector<int>> edges_of_node;  // vertex node -> boundary edges
  std::vector<const mesh::BoundaryEdge*> edges;
  // The edge's mesh edges by geometry, not by their marker: where boundary segments meet in a
  // straight line the marker of the piece at the junction may be the neighbour's.
  std::vector<std::pair<mesh::Point, mesh::Point>> pieces;
  for (const mesh::Segment& seg : problem.geometry.segments)
    if (seg.boundary == marker)
      pieces.push_back({problem.geometry.points[seg.a], problem.geometry.points[seg.b]});
  auto on_piece = [&](int node, const std::pair<mesh::Point, mesh::Point>& piece) {
    const mesh::Point& p = mesh.nodes[node];
    const double dr = piece.second.r - piece.first.r, dz = piece.second.z - piece.first.z;
    const double length2 = dr * dr + dz * dz;
    const double t = ((p.r - piece.first.r) * dr + (p.z - piece.first.z) * dz) / length2;
    const double cross = (p.z - piece.first.z) * dr - (p.r - piece.first.r) * dz;
    return t >= -1e-9 && t <= 1 + 1e-9 && std::abs(cross) <= 1e-9 * length2;
  };
  auto on_edge = [&](const mesh::BoundaryEdge& e) {
    if (pieces.empty()) return e.boundary == marker;
    if (e.boundary < 0) return false;
    const auto kind = problem.boundaries[e.boundary].kind;
    if (kind != cases::BoundaryKind::periodic && kind != cases::BoundaryKind::antiperiodic)
      return false;
    return std::any_of(pieces.begin(), pieces.end(), [&](const auto& piece) {
      return on_piece(e.nodes[0], piece) && on_piece(e.nodes[1], piece);
    });
  };
  for (const mesh::BoundaryEdge& e : mesh.boundary_edges) {
    if (!on_edge(e)) continue;
    edges_of_node[e.nodes[0]].push_back(static_cast<int>(edges.size()));
    edges_of_node[e.nodes[1]].push_back(static_cast<int>(edges.size()));
    edges.push_back(&e);
  }
  const std::string name = boundary_name(problem, marker);
  if (edges.empty())
    throw InputError(name + ": one of its edges has no mesh edge (does it bound a meshed region?)");
  // Mesh boundary edges run with the meshed domain on their left: the path starts at the node
  // that begins an edge and ends none.
  std::map<int, int> balance;  // node -> (edges starting) - (edges ending)
  for (const mesh::BoundaryEdge* e : edges) ++balance[e->nodes[0]], --balance[e->nodes[1]];
  std::vector<int> ends;
  int node = -1;
  for (const auto& [n, list] : edges_of_node) {
    if (list.size() > 2)
      throw InputError(name + ": its mesh edges branch at (" + std::to_string(mesh.nodes[n].r) +
                       ", " + std::to_string(mesh.nodes[n].z) +
                       ") m; each edge of a pair must be one unbroken line or arc");
    if (list.size() == 1) ends.push_back(n);
    if (list.size() == 1 && balance[n] > 0) node = n;
  }
  if (ends.size() != 2)
    throw InputError(name + ": its mesh edges do not form one open path (" +
                     std::to_string(ends.size()) +
                     " ends); each edge of a pair must be one unbroken line or arc");
  if (node < 0) node = ends[0];  // an edge inside the domain: no side to follow
  Path path;
  std::vector<bool> used(edges.size(), false);
  std::vector<double> arc;  // cumulative length at each edge's end
  for (std::size_t k = 0; k < edges.size(); ++k) {
    int next = -1;
    for (int candidate : edges_of_node[node])
      if (!used[candidate]) next = candidate;
    if (next < 0)
      throw InputError(name +
                       ": its mesh edges do not form one open path (disconnected); each "
                       "edge of a pair must be one unbroken line or arc");
    used[next] = true;
    const mesh::BoundaryEdge& e = *edges[next];
    PathEdge step;
    step.from = node;
    step.to = e.nodes[0] == node ? e.nodes[1] : e.nodes[0];
    step.mid = e.nodes[2];
    path.length += std::hypot(mesh.nodes[step.to].r - mesh.nodes[node].r,
                              mesh.nodes[step.to].z - mesh.nodes[node].z);
    arc.push_back(path.length);
    path.edges.push_back(step);
    node = step.to;
  }
  for (std::size_t k = 0; k < path.edges.size(); ++k) {
    path.edges[k].t0 = k == 0 ? 0.0 : arc[k - 1] / path.length;
    path.edges[k].t1 = arc[k] / path.length;
  }
  return path;
}

/// The master path's trace at parameter t as node terms (P1 or P2 edge shape functions).
std::vector<NodeTerm> interpolate(const Path& master, double t, double sign) {
  constexpr double kSnap = 1e-9;
  auto edge = std::lower_bound(master.edges.begin(), master.edges.end(), t,
                               [](const PathEdge& e, double value) { return e.t1 < value; });
  if (edge == master.edges.end()) edge = std::prev(master.edges.end());
  const double xi = std::clamp((t - edge->t0) / (edge->t1 - edge->t0), 0.0, 1.0);
  if (xi <= kSnap) return {{edge->from, sign}};
  if (xi >= 1.0 - kSnap) return {{edge->to, sign}};
  if (edge->mid < 0) return {{edge->from, sign * (1.0 - xi)}, {edge->to, sign * xi}};
  return {{edge->from, sign * (1.0 - xi) * (1.0 - 2.0 * xi)},
          {edge->to, sign * xi * (2.0 * xi - 1.0)},
          {edge->mid, sign * 4.0 * xi * (1.0 - xi)}};
}

/// Adds w x terms to `out`, merging equal nodes.
void add_terms(std::vector<NodeTerm>& out, const std::vector<NodeTerm>& terms, double w) {
  for (const NodeTerm& term : terms) {
    auto same = std::find_if(out.begin(), out.end(),
                             [&](const NodeTerm& o) { return o.node == term.node; });
    if (same == out.end())
      out.push_back({term.node, w * term.weight});
    else
      same->weight += w * term.weight;
  }
}

}  // namespace

bool PeriodicConstraints::any() const {
  return std::find(slave.begin(), slave.end(), true) != slave.end();
}

PeriodicConstraints periodic_constraints(const mesh::Mesh& mesh, const cases::Problem& problem,
                                         const std::vector<bool>& fixed) {
  PeriodicConstraints c;
  c.slave.assign(mesh.nodes.size(), false);
  c.terms.resize(mesh.nodes.size());
  for (int m = 0; m < static_cast<int>(problem.boundaries.size()); ++m) {
    const cases::BoundaryCondition& bc = problem.boundaries[m];
    const bool anti = bc.kind == cases::BoundaryKind::antiperiodic;
    if ((bc.kind != cases::BoundaryKind::periodic && !anti) || bc.partner < m) continue;
    if (bc.partner >= static_cast<int>(problem.boundaries.size()) ||
        problem.boundaries[bc.partner].partner != m)
      throw InputError(boundary_name(problem, m) + " has no partner edge");
    const Path master = boundary_path(mesh, problem, m);
    const Path slave = boundary_path(mesh, problem, bc.partner);
    if (!bc.pairs_by_angle &&
        std::abs(master.length - slave.length) > 1e-6 * std::max(master.length, slave.length))
      throw InputError(boundary_name(problem, m) + ": the paired edges have different lengths (" +
                       std::to_string(master.length) + " and " + std::to_string(slave.length) +
                       " m); periodic edges must be congruent");
    c.antiperiodic = c.antiperiodic || anti;
    const double sign = anti ? -1.0 : 1.0;
    auto constrain = [&](int node, double t) {
      if (node < 0 || fixed[node] || c.slave[node]) return;  // prescribed, or on an earlier pair
      c.slave[node] = true;
      c.terms[node] = interpolate(master, t, sign);
    };
    // Both paths run with the domain on their left: the slave's end pairs with the master's
    // start (FEMM's rule, a translation or rotation of the domain onto itself).
    for (const PathEdge& e : slave.edges) {
      constrain(e.from, 1.0 - e.t0);
      constrain(e.to, 1.0 - e.t1);
      constrain(e.mid, 1.0 - 0.5 * (e.t0 + e.t1));
    }
  }
  // Chains (a master node that is itself a slave, at corners of two pairs): substitute until
  // every constraint refers to non-slave nodes only; a node that refers to itself with weight c
  // has A (1 - c) = rest.
  const int nodes = static_cast<int>(mesh.nodes.size());
  for (int pass = 0; pass <= nodes; ++pass) {
    bool changed = false;
    for (int s = 0; s < nodes; ++s) {
      if (!c.slave[s]) continue;
      std::vector<NodeTerm> resolved;
      double self = 0.0;
      for (const NodeTerm& term : c.terms[s]) {
        if (term.node == s) {
          self += term.weight;
        } else if (c.slave[term.node]) {
          add_terms(resolved, c.terms[term.node], term.weight);
          changed = true;
        } else {
          add_terms(resolved, {term}, 1.0);
        }
      }
      if (self != 0.0) {
        changed = true;
        if (std::abs(1.0 - self) < 1e-12) {  // A = A: no constraint after all
          c.slave[s] = false;
          resolved.clear();
        } else {
          for (NodeTerm& term : resolved) term.weight /= 1.0 - self;
        }
      }
      std::erase_if(resolved, [](const NodeTerm& t) { return t.weight == 0.0; });
      c.terms[s] = std::move(resolved);
    }
    if (!changed) return c;
  }
  throw InputError(problem.geometry.source +
                   ": the periodic boundary pairs form a chain that does not resolve");
}

}  // namespace rheomag::magnetostatics
