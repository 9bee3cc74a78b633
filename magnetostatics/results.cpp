#include "magnetostatics/results.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/constants.hpp"

namespace rheomag::magnetostatics {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::array<mesh::Point, 3> vertices(const mesh::Mesh& m, int e) {
  const auto& t = m.triangles[e];
  return {m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]]};
}

/// Reference coordinates (xi, eta) of p in triangle v; inside when all barycentrics >= -tol.
bool locate(const std::array<mesh::Point, 3>& v, mesh::Point p, double& xi, double& eta) {
  const double r10 = v[1].r - v[0].r, r20 = v[2].r - v[0].r;
  const double z10 = v[1].z - v[0].z, z20 = v[2].z - v[0].z;
  const double det = r10 * z20 - r20 * z10;
  const double dr = p.r - v[0].r, dz = p.z - v[0].z;
  xi = (z20 * dr - r20 * dz) / det;
  eta = (-z10 * dr + r10 * dz) / det;
  const double tol = 1e-12;
  return xi >= -tol && eta >= -tol && xi + eta <= 1.0 + tol;
}

/// Running min / max / sum of a sampled quantity.
struct Accumulator {
  double sum = 0.0, weight = 0.0;
  double minimum = std::numeric_limits<double>::infinity();
  double maximum = -std::numeric_limits<double>::infinity();
  void add(double value, double w) {
    sum += w * value, weight += w;
    minimum = std::min(minimum, value), maximum = std::max(maximum, value);
  }
  FieldStats stats() const {
    if (weight <= 0.0) return {kNaN, kNaN, kNaN};
    return {sum / weight, minimum, maximum};
  }
};

std::array<double, 2> b_at(const MagnetostaticSolver& solver, const Solution& solution, int e,
                           double xi, double eta) {
  const mesh::Mesh& m = solver.mesh();
  double n[kMaxElementNodes], gr[kMaxElementNodes], gz[kMaxElementNodes];
  b_operator(solver.problem().symmetry, m.order, vertices(m, e), xi, eta, n, gr, gz);
  double br = 0.0, bz = 0.0;
  for (int i = 0; i < m.nodes_per_triangle(); ++i) {
    const double a = solution.a[m.triangles[e][i]];
    br += a * gr[i], bz += a * gz[i];
  }
  return {br, bz};
}

void element_fields(const MagnetostaticSolver& solver, const Solution& solution, Results& res) {
  const mesh::Mesh& m = solver.mesh();
  const Assembler& assembler = solver.assembler();
  const int elements = static_cast<int>(m.triangles.size()), k = m.nodes_per_triangle();
  const std::size_t nodes = m.nodes.size();
  for (auto* v : {&res.element_br, &res.element_bz, &res.element_b, &res.element_hr,
                  &res.element_hz, &res.element_h, &res.element_mu_r}) {
    v->assign(elements, 0.0);
  }
  for (auto* v : {&res.node_br, &res.node_bz, &res.node_b, &res.node_hr, &res.node_hz, &res.node_h,
                  &res.node_mu_r}) {
    v->assign(nodes, 0.0);
  }
  std::vector<double> node_weight(nodes, 0.0);
  static constexpr double kNodeXi[6] = {0.0, 1.0, 0.0, 0.5, 0.5, 0.0};
  static constexpr double kNodeEta[6] = {0.0, 0.0, 1.0, 0.0, 0.5, 0.5};
  ElementQuadrature q;
  double a_local[kMaxElementNodes];
  for (int e = 0; e < elements; ++e) {
    assembler.quadrature(e, q);
    const auto& t = m.triangles[e];
    for (int i = 0; i < k; ++i) a_local[i] = solution.a[t[i]];
    double area = 0.0, br = 0.0, bz = 0.0, energy = 0.0, b_dot_h = 0.0;
    const Reluctivity& law = assembler.law(e);
    for (int p = 0; p < q.points; ++p) {
      const auto b = element_b(q, p, a_local);
      const auto h = law.h(b[0], b[1]);
      area += q.area_weight[p];
      br += q.area_weight[p] * b[0], bz += q.area_weight[p] * b[1];
      energy += q.weight[p] * law.energy_density(b[0], b[1]);
      b_dot_h += q.weight[p] * (h[0] * b[0] + h[1] * b[1]);
    }
    res.energy += energy;
    res.coenergy += b_dot_h - energy;
    br /= area, bz /= area;
    const auto [hr, hz] = law.h(br, bz);
    res.element_br[e] = br, res.element_bz[e] = bz, res.element_b[e] = std::hypot(br, bz);
    res.element_hr[e] = hr, res.element_hz[e] = hz;
    res.element_h[e] = std::hypot(hr, hz);
    res.element_mu_r[e] = law.apparent_mu_r(br, bz);
    for (int i = 0; i < k; ++i) {
      const auto b = b_at(solver, solution, e, kNodeXi[i], kNodeEta[i]);
      const auto h = law.h(b[0], b[1]);
      const int node = t[i];
      node_weight[node] += area;
      res.node_br[node] += area * b[0], res.node_bz[node] += area * b[1];
      res.node_b[node] += area * std::hypot(b[0], b[1]);
      res.node_hr[node] += area * h[0], res.node_hz[node] += area * h[1];
      res.node_h[node] += area * std::hypot(h[0], h[1]);
      res.node_mu_r[node] += area * law.apparent_mu_r(b[0], b[1]);
    }
  }
  for (std::size_t i = 0; i < nodes; ++i) {
    if (node_weight[i] <= 0.0) continue;
    for (auto* v : {&res.node_br, &res.node_bz, &res.node_b, &res.node_hr, &res.node_hz,
                    &res.node_h, &res.node_mu_r}) {
      (*v)[i] /= node_weight[i];
    }
  }
}

GapResult gap_result(const MagnetostaticSolver& solver, const Solution& solution, int region) {
  const mesh::Mesh& m = solver.mesh();
  const mesh::RegionSeed& seed = solver.problem().geometry.regions[region];
  GapResult gap;
  gap.name = seed.name;
  gap.kind = seed.gap;
  gap.region = region;
  const bool annular = seed.gap == mesh::GapKind::annular;
  auto normal = [annular](const std::array<double, 2>& b) {
    return std::abs(annular ? b[0] : b[1]);
  };
  std::vector<int> elements;
  double r_min = std::numeric_limits<double>::infinity(), r_max = -r_min, z_min = r_min,
         z_max = -r_min;
  Accumulator b_area, bn_area;
  ElementQuadrature q;
  double a_local[kMaxElementNodes];
  for (int e = 0; e < static_cast<int>(m.triangles.size()); ++e) {
    if (m.region[e] != region) continue;
    elements.push_back(e);
    for (const mesh::Point& p : vertices(m, e)) {
      r_min = std::min(r_min, p.r), r_max = std::max(r_max, p.r);
      z_min = std::min(z_min, p.z), z_max = std::max(z_max, p.z);
    }
    solver.assembler().quadrature(e, q);
    for (int i = 0; i < m.nodes_per_triangle(); ++i) a_local[i] = solution.a[m.triangles[e][i]];
    for (int p = 0; p < q.points; ++p) {
      const auto b = element_b(q, p, a_local);
      b_area.add(std::hypot(b[0], b[1]), q.area_weight[p]);
      bn_area.add(normal(b), q.area_weight[p]);
      gap.area += q.area_weight[p];
    }
  }
  gap.b = b_area.stats();
  gap.b_normal = bn_area.stats();
  if (elements.empty()) {
    gap.line_b = gap.line_b_normal = {kNaN, kNaN, kNaN};
    return gap;
  }
  // Mid-line along the gap's long direction: z for an annular gap, r for a radial one.
  if (annular) {
    gap.line_start = {0.5 * (r_min + r_max), z_min}, gap.line_end = {0.5 * (r_min + r_max), z_max};
  } else {
    gap.line_start = {r_min, 0.5 * (z_min + z_max)}, gap.line_end = {r_max, 0.5 * (z_min + z_max)};
  }
  // Samples at the centres of kGapLineSamples equal parts of a line parallel to the mid-line,
  // shifted across the gap by `across` (in the normal direction), kept where it lies in the gap.
  const double inset = 1e-6 * (annular ? r_max - r_min : z_max - z_min);
  auto sample = [&](double across) {
    GapProfile profile;
    const mesh::Point start{gap.line_start.r + (annular ? across : 0.0),
                            gap.line_start.z + (annular ? 0.0 : across)};
    const double length =
        std::hypot(gap.line_end.r - gap.line_start.r, gap.line_end.z - gap.line_start.z);
    for (int s = 0; s < kGapLineSamples; ++s) {
      const double t = (s + 0.5) / kGapLineSamples;
      const mesh::Point p{start.r + t * (gap.line_end.r - gap.line_start.r),
                          start.z + t * (gap.line_end.z - gap.line_start.z)};
      for (int e : elements) {
        double xi, eta;
        if (!locate(vertices(m, e), p, xi, eta)) continue;
        const auto b = b_at(solver, solution, e, xi, eta);
        profile.s.push_back(t * length);
        profile.b_n.push_back(annular ? b[0] : b[1]);
        profile.b_t.push_back(annular ? b[1] : b[0]);
        break;
      }
    }
    return profile;
  };
  gap.profile = sample(0.0);
  const double half_width = 0.5 * (annular ? r_max - r_min : z_max - z_min) - inset;
  gap.walls = {sample(-half_width), sample(half_width)};
  Accumulator b_line, bn_line;
  for (std::size_t i = 0; i < gap.profile.s.size(); ++i) {
    b_line.add(std::hypot(gap.profile.b_n[i], gap.profile.b_t[i]), 1.0);
    bn_line.add(std::abs(gap.profile.b_n[i]), 1.0);
    ++gap.line_samples;
  }
  gap.line_b = b_line.stats();
  gap.line_b_normal = bn_line.stats();
  return gap;
}

}  // namespace

std::optional<MeshLocation> locate_in_mesh(const mesh::Mesh& m, mesh::Point p, int region) {
  for (int e = 0; e < static_cast<int>(m.triangles.size()); ++e) {
    if (region >= 0 && m.region[e] != region) continue;
    double xi, eta;
    if (locate(vertices(m, e), p, xi, eta)) return MeshLocation{e, xi, eta};
  }
  return std::nullopt;
}

std::array<double, 2> flux_density_in(const MagnetostaticSolver& solver, const Solution& solution,
                                      const MeshLocation& at) {
  return b_at(solver, solution, at.element, at.xi, at.eta);
}

bool flux_density_at(const MagnetostaticSolver& solver, const Solution& solution, mesh::Point p,
                     int region, std::array<double, 2>& b) {
  const std::optional<MeshLocation> at = locate_in_mesh(solver.mesh(), p, region);
  if (!at) return false;
  b = flux_density_in(solver, solution, *at);
  return true;
}

Results compute_results(const MagnetostaticSolver& solver, const Solution& solution) {
  Results res;
  const cases::Problem& problem = solver.problem();
  element_fields(solver, solution, res);
  const double exterior = solver.assembler().boundary_energy(solution.a);
  res.energy += exterior;
  res.coenergy += exterior;
  for (int region = 0; region < static_cast<int>(problem.geometry.regions.size()); ++region) {
    if (problem.geometry.regions[region].gap != mesh::GapKind::none &&
        !problem.geometry.regions[region].hole) {
      res.gaps.push_back(gap_result(solver, solution, region));
    }
  }
  for (int c = 0; c < static_cast<int>(problem.circuits.size()); ++c) {
    CircuitResult circuit;
    circuit.name = problem.circuits[c].name;
    circuit.current = solution.currents[c];
    bool wound = false;
    for (const cases::RegionData& region : problem.regions) {
      if (region.circuit == c) circuit.turns += region.turns;
      wound = wound || (region.circuit == c && region.turns != 0.0);
    }
    if (problem.circuits[c].parallel) circuit.turns = 1.0;  // one current shared, FEMM's way
    if (!wound && circuit.current != 0.0)
      circuit.warning = "circuit '" + circuit.name +
                        "' carries a current but winds no region (no block label names it with "
                        "turns): it makes no field and links no flux, so lambda = 0; assign it to "
                        "the coil's block labels";
    circuit.flux_linkage = solution.flux_linkage[c];
    circuit.incremental_inductance = c < static_cast<int>(solution.incremental_inductance.size())
                                         ? solution.incremental_inductance[c]
                                         : kNaN;
    circuit.inductance = circuit.current != 0.0 ? circuit.flux_linkage / circuit.current
                                                : circuit.incremental_inductance;
    circuit.gauge_free = solver.flux_linkage_gauge_free(c);
    if (!circuit.gauge_free) {
      circuit.flux_linkage = circuit.inductance = circuit.incremental_inductance =
          std::numeric_limits<double>::quiet_NaN();
    }
    res.circuits.push_back(circuit);
  }
  res.newton_iterations = solution.newton.iterations;
  res.residual_history = solution.newton.residual_history;
  res.dofs = solver.dofs().free_count();
  res.elements = static_cast<int>(solver.mesh().triangles.size());
  res.nodes = static_cast<int>(solver.mesh().nodes.size());
  res.seconds = solution.seconds;
  return res;
}

std::vector<SweepPoint> sweep_with_gaps(MagnetostaticSolver& solver, int circuit,
                                        const std::vector<double>& currents) {
  return solver.sweep(circuit, currents, [&solver](const Solution& s, SweepPoint& point) {
    for (const GapResult& g : compute_results(solver, s).gaps)
      point.gaps.push_back({g.name, g.b.average, g.line_b.maximum, g.b.maximum});
  });
}

}  // namespace rheomag::magnetostatics
