// The coarse constrained triangulation of a PSLG and its flood fill (see cdt_insert.hpp).

#include "mesh/cdt_insert.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <stdexcept>
#include <vector>

namespace rheomag::mesh::detail {

namespace {

void set_edge_data(const Cdt& cdt, Cdt::Vertex_handle va, Cdt::Vertex_handle vb, int boundary,
                   double max_length) {
  Cdt::Face_handle f;
  int i = 0;
  if (!cdt.is_edge(va, vb, f, i))
    throw std::logic_error("rheomag mesh: a validated segment is not an edge of the CDT");
  Cdt::Face_handle n = f->neighbor(i);
  const int j = n->index(f);
  f->info().boundary[i] = n->info().boundary[j] = boundary;
  f->info().max_length[i] = n->info().max_length[j] = max_length;
}

}  // namespace

// Gives `label` to every still unlabelled face reachable from `start` without crossing a
// constrained edge.
void flood_fill(const Cdt& cdt, Cdt::Face_handle start, int label) {
  std::queue<Cdt::Face_handle> queue;
  start->info().region = label;
  queue.push(start);
  while (!queue.empty()) {
    Cdt::Face_handle f = queue.front();
    queue.pop();
    for (int i = 0; i < 3; ++i) {
      Cdt::Face_handle n = f->neighbor(i);
      if (cdt.is_constrained({f, i}) || n->info().region != kUnlabelled) continue;
      n->info().region = label;
      queue.push(n);
    }
  }
}

void insert_pslg(const PreparedPslg& prepared, Cdt& cdt, SegmentPieces pieces) {
  struct ConstrainedEdge {
    Cdt::Vertex_handle a, b;
    int boundary;
    double max_length;
  };
  // Pieces per segment (prepare_pslg has bounded their total by kMaxSegmentPieces).
  std::vector<int> pieces_of(prepared.segments.size(), 1);
  for (std::size_t k = 0; k < prepared.segments.size(); ++k) {
    const PreparedSegment& s = prepared.segments[k];
    const Point& a = prepared.points[static_cast<std::size_t>(s.a)];
    const Point& b = prepared.points[static_cast<std::size_t>(s.b)];
    if (pieces == SegmentPieces::cut && s.max_length > 0.0)
      pieces_of[k] = static_cast<int>(std::clamp(
          std::ceil(std::hypot(b.r - a.r, b.z - a.z) / s.max_length), 1.0, kMaxSegmentPieces));
  }
  std::vector<Cdt::Vertex_handle> vertex;
  vertex.reserve(prepared.points.size());
  for (const Point& p : prepared.points) vertex.push_back(cdt.insert(CgalPoint(p.r, p.z)));
  std::vector<ConstrainedEdge> edges;
  for (std::size_t k = 0; k < prepared.segments.size(); ++k) {
    const PreparedSegment& s = prepared.segments[k];
    const Point& a = prepared.points[static_cast<std::size_t>(s.a)];
    const Point& b = prepared.points[static_cast<std::size_t>(s.b)];
    const int n = pieces_of[k];
    Cdt::Vertex_handle from = vertex[static_cast<std::size_t>(s.a)];
    for (int k = 1; k <= n; ++k) {
      const double t = static_cast<double>(k) / n;
      Cdt::Vertex_handle to =
          k == n ? vertex[static_cast<std::size_t>(s.b)]
                 : cdt.insert(CgalPoint(a.r + t * (b.r - a.r), a.z + t * (b.z - a.z)));
      cdt.insert_constraint(from, to);
      edges.push_back({from, to, s.boundary, s.max_length});
      from = to;
    }
  }
  // Markers are set once all constraints are in, when no edge can be split any more.
  for (const ConstrainedEdge& e : edges) set_edge_data(cdt, e.a, e.b, e.boundary, e.max_length);
}

}  // namespace rheomag::mesh::detail
