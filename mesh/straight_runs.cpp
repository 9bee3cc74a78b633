// The pieces of a cut segment joined back into straight runs (see straight_runs.hpp).

#include "mesh/straight_runs.hpp"

#include <cmath>
#include <cstddef>
#include <map>

namespace rheomag::mesh::detail {

namespace {

using Point = std::array<double, 2>;

/// True when p -> v -> q goes on straight through v (to 1e-9 of the two lengths).
bool continues_straight(const Point& p, const Point& v, const Point& q) {
  const double ux = v[0] - p[0], uy = v[1] - p[1], wx = q[0] - v[0], wy = q[1] - v[1];
  const double lengths = std::hypot(ux, uy) * std::hypot(wx, wy);
  return ux * wx + uy * wy > 0.0 && std::abs(ux * wy - uy * wx) <= 1e-9 * lengths;
}

/// The end of `e` that is not `v`.
const Point& far_end(const SizedEdge& e, const Point& v) {
  return e.a == v ? e.b : e.a;
}

}  // namespace

std::vector<SizedEdge> merge_straight_runs(const std::vector<SizedEdge>& edges) {
  std::map<Point, std::vector<std::size_t>> at_point;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    at_point[edges[i].a].push_back(i);
    at_point[edges[i].b].push_back(i);
  }
  std::vector<bool> used(edges.size(), false);
  // The unused edge that continues `edge` straight on through its end `v` with the same size,
  // or edges.size() if there is none.
  auto next_through = [&](std::size_t edge, const Point& v) {
    const std::vector<std::size_t>& here = at_point.at(v);
    if (here.size() != 2) return edges.size();
    const std::size_t other = here[0] == edge ? here[1] : here[0];
    if (used[other] || edges[other].size != edges[edge].size ||
        !continues_straight(far_end(edges[edge], v), v, far_end(edges[other], v)))
      return edges.size();
    return other;
  };
  std::vector<SizedEdge> runs;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (used[i]) continue;
    used[i] = true;
    SizedEdge run = edges[i];
    for (Point* end : {&run.b, &run.a}) {
      for (std::size_t edge = i, next; (next = next_through(edge, *end)) < edges.size();
           edge = next) {
        used[next] = true;
        *end = far_end(edges[next], *end);
      }
    }
    runs.push_back(run);
  }
  return runs;
}

}  // namespace rheomag::mesh::detail
