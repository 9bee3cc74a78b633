#include "magnetostatics/stress_tensor.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "core/error.hpp"
#include "mesh/edge_key.hpp"
#include "mesh/triangle.hpp"

namespace rheomag::magnetostatics {
namespace {

constexpr double kUnset = -1.0;

/// Physical gradients (d/dr, d/dz) of the shape functions of triangle `v` at (xi, eta).
void shape_gradients(int order, const std::array<mesh::Point, 3>& v, double xi, double eta,
                     double* d_r, double* d_z) {
  double value[kMaxElementNodes], d_xi[kMaxElementNodes], d_eta[kMaxElementNodes];
  lagrange_basis(order, xi, eta, value, d_xi, d_eta);
  const double r10 = v[1].r - v[0].r, r20 = v[2].r - v[0].r;
  const double z10 = v[1].z - v[0].z, z20 = v[2].z - v[0].z;
  const double det = r10 * z20 - r20 * z10;
  const int nodes = order == 1 ? 3 : 6;
  for (int i = 0; i < nodes; ++i) {
    d_r[i] = (z20 * d_xi[i] - z10 * d_eta[i]) / det;
    d_z[i] = (-r20 * d_xi[i] + r10 * d_eta[i]) / det;
  }
}

std::array<mesh::Point, 3> triangle_vertices(const mesh::Mesh& m, int e) {
  const auto& t = m.triangles[e];
  return {m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]]};
}

/// Nodes on the outer boundary of the mesh (edges of one triangle only), midpoints included.
std::vector<char> mesh_boundary_nodes(const mesh::Mesh& m) {
  std::unordered_map<std::uint64_t, int> count;
  static constexpr int kEdge[3][3] = {{0, 1, 3}, {1, 2, 4}, {2, 0, 5}};
  for (const auto& t : m.triangles)
    for (const auto& e : kEdge) ++count[mesh::edge_key(t[e[0]], t[e[1]])];
  std::vector<char> boundary(m.nodes.size(), 0);
  for (const auto& t : m.triangles) {
    for (const auto& e : kEdge) {
      if (count[mesh::edge_key(t[e[0]], t[e[1]])] != 1) continue;
      boundary[t[e[0]]] = boundary[t[e[1]]] = 1;
      if (m.order == 2) boundary[t[e[2]]] = 1;
    }
  }
  return boundary;
}

/// True when region `region` carries no source: no coil, no fixed current density, no magnet.
bool source_free(const cases::Problem& problem, int region) {
  const cases::RegionData& data = problem.regions[region];
  if (data.circuit >= 0 || data.current_density != 0.0 || data.material < 0) return false;
  return problem.materials[data.material].coercivity == 0.0;
}

/// The medium of `region` a body can move through: -1 for free space, the material index for a
/// source-free fluid, kSolid for anything else.
constexpr int kSolid = -2;
int medium_of(const cases::Problem& problem, int region) {
  if (is_air_region(problem, region)) return -1;
  const int material = problem.regions[region].material;
  return source_free(problem, region) && problem.materials[material].fluid ? material : kSolid;
}

/// Fills out.junctions with the points of `junctions` and out.junction_size with the longest
/// triangle edge at them.
void junction_report(const mesh::Mesh& m, const std::vector<int>& junctions,
                     StressTensorForce& out) {
  std::vector<char> at(m.nodes.size(), 0);
  for (int node : junctions) at[node] = 1, out.junctions.push_back(m.nodes[node]);
  for (const auto& t : m.triangles) {
    if (!at[t[0]] && !at[t[1]] && !at[t[2]]) continue;
    for (int i = 0; i < 3; ++i) {
      const mesh::Point a = m.nodes[t[i]], b = m.nodes[t[(i + 1) % 3]];
      out.junction_size = std::max(out.junction_size, std::hypot(a.r - b.r, a.z - b.z));
    }
  }
}

}  // namespace

bool is_air_region(const cases::Problem& problem, int region) {
  const cases::RegionData& data = problem.regions[region];
  if (data.circuit >= 0 || data.current_density != 0.0 || data.material < 0) return false;
  const cases::Material& material = problem.materials[data.material];
  return material.mu_r == 1.0 && !material.mu_r_axes && material.bh.empty() &&
         material.coercivity == 0.0;
}

Eigen::VectorXd stress_tensor_mask(const MagnetostaticSolver& solver,
                                   const std::vector<int>& selected, std::vector<int>* junctions) {
  const mesh::Mesh& m = solver.mesh();
  const cases::Problem& problem = solver.problem();
  if (selected.empty()) throw InputError("force/torque: no region selected");
  const int k = m.nodes_per_triangle();
  std::vector<char> chosen(problem.regions.size(), 0);
  for (int region : selected) chosen[region] = 1;

  // Prescribed values: outer boundary 0 (off the axis), selected 1.
  std::vector<double> fixed(m.nodes.size(), kUnset);
  const std::vector<char> boundary = mesh_boundary_nodes(m);
  double extent = 0.0;
  for (const mesh::Point& p : m.nodes) extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
  const bool axisymmetric = problem.symmetry == cases::Symmetry::axisymmetric;
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    if (boundary[i] && !(axisymmetric && m.nodes[i].r <= 1e-12 * extent)) fixed[i] = 0.0;
  }
  std::vector<int> owner(m.nodes.size(), -1);  // selected region that set a node to 1
  for (std::size_t e = 0; e < m.triangles.size(); ++e) {
    if (!chosen[m.region[e]]) continue;
    for (int i = 0; i < k; ++i)
      fixed[m.triangles[e][i]] = 1.0, owner[m.triangles[e][i]] = m.region[e];
  }
  // Every other region is a solid (0 on its nodes; a body touching one is refused) or a medium
  // (air or a fluid): the mask is harmonic in each medium, and the interfaces between two media
  // stay put (0) except where they meet the body.
  std::vector<int> medium_at(m.nodes.size(), kSolid - 1);  // first medium seen at each node
  std::vector<char> interface(m.nodes.size(), 0);
  for (std::size_t e = 0; e < m.triangles.size(); ++e) {
    const int region = m.region[e];
    if (chosen[region]) continue;
    const int medium = medium_of(problem, region);
    for (int i = 0; i < k; ++i) {
      const int node = m.triangles[e][i];
      if (medium != kSolid) {
        if (medium_at[node] == kSolid - 1) medium_at[node] = medium;
        if (medium_at[node] != medium) interface[node] = 1;
        continue;
      }
      if (owner[node] >= 0) {
        throw InputError("force/torque on region '" + problem.geometry.regions[owner[node]].name +
                         "': it touches region '" + problem.geometry.regions[region].name +
                         "', which is neither air nor a fluid; the stress tensor needs a layer of "
                         "air or fluid around the selected regions (select both, or add an air "
                         "region between)");
      }
      fixed[node] = 0.0;
    }
  }
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    if (interface[i] && owner[i] < 0) fixed[i] = 0.0;
    if (interface[i] && owner[i] >= 0 && junctions) junctions->push_back(static_cast<int>(i));
  }

  // Laplace's equation for the free nodes: sum_e integral grad N_i . grad N_j dA w_j = 0.
  std::vector<int> index(m.nodes.size(), -1);
  int free_count = 0;
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    if (fixed[i] == kUnset) index[i] = free_count++;
  Eigen::VectorXd w(static_cast<Eigen::Index>(m.nodes.size()));
  for (std::size_t i = 0; i < m.nodes.size(); ++i) w[i] = fixed[i] == kUnset ? 0.0 : fixed[i];
  if (free_count == 0) return w;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(free_count);
  const auto& rule = triangle_quadrature(m.order);
  double d_r[kMaxElementNodes], d_z[kMaxElementNodes];
  for (std::size_t e = 0; e < m.triangles.size(); ++e) {
    const auto& t = m.triangles[e];
    bool any_free = false;
    for (int i = 0; i < k; ++i) any_free = any_free || index[t[i]] >= 0;
    if (!any_free) continue;
    const auto v = triangle_vertices(m, static_cast<int>(e));
    const double area = mesh::triangle_area(v[0], v[1], v[2]);
    double ke[kMaxElementNodes][kMaxElementNodes] = {};
    for (const TriangleQuadraturePoint& q : rule) {
      shape_gradients(m.order, v, q.xi, q.eta, d_r, d_z);
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j)
          ke[i][j] += q.weight * area * (d_r[i] * d_r[j] + d_z[i] * d_z[j]);
    }
    for (int i = 0; i < k; ++i) {
      const int row = index[t[i]];
      if (row < 0) continue;
      for (int j = 0; j < k; ++j) {
        const int col = index[t[j]];
        if (col >= 0)
          entries.emplace_back(row, col, ke[i][j]);
        else
          rhs[row] -= ke[i][j] * fixed[t[j]];
      }
    }
  }
  Eigen::SparseMatrix<double> matrix(free_count, free_count);
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(matrix);
  if (ldlt.info() != Eigen::Success)
    throw ConvergenceError("force/torque: the mask's Laplace matrix could not be factorised");
  const Eigen::VectorXd x = ldlt.solve(rhs);
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    if (index[i] >= 0) w[i] = x[index[i]];
  return w;
}

StressTensorForce stress_tensor_force(const MagnetostaticSolver& solver, const Solution& solution,
                                      const std::vector<int>& selected) {
  std::vector<int> junctions;
  const Eigen::VectorXd w = stress_tensor_mask(solver, selected, &junctions);
  const mesh::Mesh& m = solver.mesh();
  const bool axisymmetric = solver.problem().symmetry == cases::Symmetry::axisymmetric;
  const int k = m.nodes_per_triangle();
  const auto& rule = triangle_quadrature(m.order);
  StressTensorForce out;
  ElementQuadrature q;
  double a_local[kMaxElementNodes], d_r[kMaxElementNodes], d_z[kMaxElementNodes];
  for (int e = 0; e < static_cast<int>(m.triangles.size()); ++e) {
    const auto& t = m.triangles[e];
    double w_min = w[t[0]], w_max = w[t[0]];
    for (int i = 1; i < k; ++i) w_min = std::min(w_min, w[t[i]]), w_max = std::max(w_max, w[t[i]]);
    if (w_max == w_min) continue;  // grad w = 0: no contribution
    solver.assembler().quadrature(e, q);
    const auto v = triangle_vertices(m, e);
    for (int i = 0; i < k; ++i) a_local[i] = solution.a[t[i]];
    for (int p = 0; p < q.points; ++p) {
      shape_gradients(m.order, v, rule[p].xi, rule[p].eta, d_r, d_z);
      double gr = 0.0, gz = 0.0;
      for (int i = 0; i < k; ++i) gr += w[t[i]] * d_r[i], gz += w[t[i]] * d_z[i];
      const auto b = element_b(q, p, a_local);
      // (T grad w)_i = H_i (B . grad w) - w' (grad w)_i, w' = B . H - w(B): the stress tensor
      // of any isotropic medium (nu0 B B - nu0 |B|^2 / 2 in free space), where the mask's
      // gradient lies (the air around the body, is_air_region).
      const Reluctivity& law = solver.assembler().law(e);
      const auto h = law.h(b[0], b[1]);
      const double coenergy_density = h[0] * b[0] + h[1] * b[1] - law.energy_density(b[0], b[1]);
      const double b_dot_g = b[0] * gr + b[1] * gz;
      const double tr = h[0] * b_dot_g - coenergy_density * gr;
      const double tz = h[1] * b_dot_g - coenergy_density * gz;
      out.force[1] -= q.weight[p] * tz;
      if (!axisymmetric) {
        out.force[0] -= q.weight[p] * tr;
        out.torque -= q.weight[p] * (q.r[p] * tz - q.z[p] * tr);
      }
    }
  }
  junction_report(m, junctions, out);
  return out;
}

}  // namespace rheomag::magnetostatics
