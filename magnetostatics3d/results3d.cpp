#include "magnetostatics3d/results3d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/constants.hpp"

namespace rheomag::magnetostatics3d {
namespace {

/// Running weighted average with minimum and maximum.
struct Accumulator {
  double sum = 0.0, weight = 0.0;
  double minimum = std::numeric_limits<double>::infinity();
  double maximum = -std::numeric_limits<double>::infinity();
  void add(double value, double w) {
    sum += w * value;
    weight += w;
    minimum = std::min(minimum, value);
    maximum = std::max(maximum, value);
  }
  void merge(const Accumulator& o) {
    sum += o.sum;
    weight += o.weight;
    minimum = std::min(minimum, o.minimum);
    maximum = std::max(maximum, o.maximum);
  }
  double average() const {
    return weight > 0 ? sum / weight : std::numeric_limits<double>::quiet_NaN();
  }
  magnetostatics::FieldStats stats() const {
    if (weight <= 0) return {average(), average(), average()};
    return {average(), minimum, maximum};
  }
};

}  // namespace

Results3d compute_results_3d(const cases::Problem& closed, const EdgeSolver& solver,
                             const EdgeSolution& solution, ModelPart part, double span) {
  const TetMesh& mesh = solver.mesh();
  Results3d res;
  res.part = part;
  res.span = span;
  const double factor = kTwoPi / span;  // whole body / meshed part
  res.dofs = solver.dofs().free_count();
  res.tetrahedra = static_cast<int>(mesh.tets.size());
  res.nodes = static_cast<int>(mesh.nodes.size());
  res.edges = static_cast<int>(mesh.edges.size());
  res.newton_iterations = solution.newton.iterations;
  res.linear_solver = solver.linear_solver();
  res.factorizations = solution.factorizations;
  res.cg_iterations = solution.cg_iterations;
  res.residual_history = solution.newton.residual_history;
  res.energy = factor * solver.stored_energy(solution.b);

  // Gaps: per region, accumulators overall and per meshed sector.
  std::vector<int> gap_of_region(closed.regions.size(), -1);
  for (std::size_t r = 0; r < closed.geometry.regions.size(); ++r) {
    const mesh::RegionSeed& seed = closed.geometry.regions[r];
    if (seed.gap == mesh::GapKind::none) continue;
    gap_of_region[r] = static_cast<int>(res.gaps.size());
    GapResult3d g;
    g.name = seed.name;
    g.kind = seed.gap;
    g.region = static_cast<int>(r);
    res.gaps.push_back(g);
  }
  std::vector<Accumulator> all(res.gaps.size()), normal(res.gaps.size());
  std::vector<std::array<Accumulator, kThetaSectors>> sector(res.gaps.size());
  for (int t = 0; t < res.tetrahedra; ++t) {
    const int g = gap_of_region[mesh.region[t]];
    if (g < 0) continue;
    const Eigen::Vector3d c = mesh.centroid(t);
    const double r = std::hypot(c[0], c[1]);
    const double v = mesh.volume(t);
    const Eigen::Vector3d& b = solution.b[t];
    const double bn =
        res.gaps[g].kind == mesh::GapKind::annular ? (b[0] * c[0] + b[1] * c[1]) / r : b[2];
    all[g].add(b.norm(), v / r);
    normal[g].add(std::abs(bn), v / r);
    res.gaps[g].volume += factor * v;
    double phi = std::atan2(c[1], c[0]);
    if (phi < 0) phi += kTwoPi;
    const int k = std::min(kThetaSectors - 1, static_cast<int>(phi / kTwoPi * kThetaSectors));
    sector[g][k].add(b.norm(), v / r);
    if (part == ModelPart::half) sector[g][kThetaSectors - 1 - k].add(b.norm(), v / r);
  }
  for (std::size_t g = 0; g < res.gaps.size(); ++g) {
    res.gaps[g].b = all[g].stats();
    res.gaps[g].b_normal = normal[g].stats();
    for (int k = 0; k < kThetaSectors; ++k) {
      res.gaps[g].b_avg_theta[k] =
          part == ModelPart::wedge ? all[g].average() : sector[g][k].average();
    }
  }

  for (std::size_t c = 0; c < closed.circuits.size(); ++c) {
    CircuitResult3d cr;
    cr.name = closed.circuits[c].name;
    cr.current = c < solution.currents.size() ? solution.currents[c] : 0.0;
    cr.flux_linkage = factor * solver.load(static_cast<int>(c)).dot(solution.a);
    cr.inductance =
        cr.current != 0.0 ? cr.flux_linkage / cr.current : std::numeric_limits<double>::quiet_NaN();
    res.circuits.push_back(cr);
  }
  return res;
}

}  // namespace rheomag::magnetostatics3d
