#include "magnetostatics/assembly.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "case/magnet_direction.hpp"
#include "core/error.hpp"
#include "mesh/triangle.hpp"

namespace rheomag::magnetostatics {
namespace {

std::atomic<int> assembly_thread_setting{1};

/// Team size of an assembly over `elements` triangles: serial below 8 chunks.
int assembly_team(int elements, int chunk) {
  const int setting = assembly_thread_setting.load(std::memory_order_relaxed);
  if (elements < 8 * chunk) return 1;
  return setting > 0 ? setting : omp_get_max_threads();
}

std::array<mesh::Point, 3> vertices(const mesh::Mesh& mesh, int e) {
  const auto& t = mesh.triangles[e];
  return {mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]]};
}

}  // namespace

void set_assembly_threads(int threads) {
  assembly_thread_setting.store(std::max(0, threads), std::memory_order_relaxed);
}

int assembly_threads() {
  return assembly_thread_setting.load(std::memory_order_relaxed);
}

Assembler::Assembler(const cases::Problem& problem, const mesh::Mesh& mesh, const DofMap& dofs)
    : problem_(problem), mesh_(mesh), dofs_(dofs), laws_(build_reluctivities(problem)) {
  if (mesh.order != 1 && mesh.order != 2) {
    throw InputError("mesh order " + std::to_string(mesh.order) + "; expected 1 or 2");
  }
  const int elements = static_cast<int>(mesh.triangles.size());
  const int m = mesh.nodes_per_triangle();
  material_of_element_.resize(elements);
  region_area_.assign(problem.regions.size(), 0.0);
  for (int e = 0; e < elements; ++e) {
    const int region = mesh.region[e];
    if (region < 0 || region >= static_cast<int>(problem.regions.size())) {
      throw InputError("mesh triangle " + std::to_string(e) + " lies in region " +
                       std::to_string(region) + ", which has no region data");
    }
    const int material = problem.regions[region].material;
    if (material < 0 || material >= static_cast<int>(laws_.size())) {
      const auto& seeds = problem.geometry.regions;
      const std::string name =
          region < static_cast<int>(seeds.size()) ? seeds[region].name : std::to_string(region);
      throw InputError("region '" + name + "' has no material");
    }
    material_of_element_[e] = material;
    const auto v = vertices(mesh, e);
    region_area_[region] += mesh::triangle_area(v[0], v[1], v[2]);
    if (problem.regions[region].kelvin_exterior && problem.kelvin) {
      // FEMM's axisymmetric external disk: mu divided by the Kelvin factor at the centroid,
      // a law of the triangle's own (the material is linear: the importer checks).
      const mesh::Point c = mesh::triangle_centroid(v[0], v[1], v[2]);
      cases::Material scaled = problem.materials[material];
      const double factor = problem.kelvin->reluctivity_factor(c.r, c.z);
      scaled.mu_r /= factor;
      if (scaled.mu_r_axes)
        for (double& mu : *scaled.mu_r_axes) mu /= factor;
      material_of_element_[e] = static_cast<int>(laws_.size());
      laws_.emplace_back(scaled);
    }
  }
  region_current_ = circuit_currents(problem, mesh, region_area_);
  for (const mesh::BoundaryEdge& edge : mesh.boundary_edges) {
    if (edge.boundary < 0 || edge.boundary >= static_cast<int>(problem.boundaries.size())) continue;
    const cases::BoundaryCondition& bc = problem.boundaries[edge.boundary];
    if (bc.kind == cases::BoundaryKind::mixed) robin_edges_.push_back({edge.nodes, bc.c0, bc.c1});
  }

  // Sparsity pattern: lower triangle of the free-dof couplings of every triangle.
  const int n = dofs.free_count();
  std::vector<std::vector<int>> rows_of_column(n);
  for (int e = 0; e < elements; ++e) {
    const auto& t = mesh.triangles[e];
    for (int i = 0; i < m; ++i) {
      const int row = dofs.dof_of_node[t[i]];
      if (row < 0) continue;
      for (int j = 0; j < m; ++j) {
        const int col = dofs.dof_of_node[t[j]];
        if (col >= 0 && row >= col) rows_of_column[col].push_back(row);
      }
    }
  }
  std::vector<int> outer(n + 1, 0), inner;
  for (int col = 0; col < n; ++col) {
    auto& rows = rows_of_column[col];
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    outer[col + 1] = outer[col] + static_cast<int>(rows.size());
    inner.insert(inner.end(), rows.begin(), rows.end());
    std::vector<int>().swap(rows);
  }
  pattern_.resize(n, n);
  pattern_.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), pattern_.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), pattern_.innerIndexPtr());
  std::fill_n(pattern_.valuePtr(), inner.size(), 0.0);

  element_offsets_.resize(static_cast<std::size_t>(elements) * m * m);
  for (int e = 0; e < elements; ++e) {
    const auto& t = mesh.triangles[e];
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m; ++j) {
        element_offsets_[(static_cast<std::size_t>(e) * m + i) * m + j] =
            matrix_offset(dofs.dof_of_node[t[i]], dofs.dof_of_node[t[j]]);
      }
    }
  }
  if (elements <= kMaxCachedElements) {
    // The geometry does not change between assemblies (a Newton solve or a time run does
    // hundreds): computed once, it saves a sixth of the element work.
    geometry_.resize(elements);
    for (int e = 0; e < elements; ++e) quadrature(e, geometry_[e]);
  }
  const int edge_nodes = mesh.order == 1 ? 2 : 3;
  build_node_adjacency(edge_nodes);
  build_colouring();
  build_linear_part();
  for (const RobinEdge& edge : robin_edges_) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        robin_offsets_.push_back(
            i < edge_nodes && j < edge_nodes
                ? matrix_offset(dofs.dof_of_node[edge.nodes[i]], dofs.dof_of_node[edge.nodes[j]])
                : -1);
      }
    }
  }
}

void Assembler::build_node_adjacency(int edge_nodes) {
  // Counting sort of (node, triangle) and (node, Robin edge) pairs into CSR arrays.
  const int nodes = static_cast<int>(mesh_.nodes.size());
  const int m = mesh_.nodes_per_triangle();
  auto build = [nodes](int items, int per_item, auto node_of, std::vector<int>& start,
                       std::vector<int>& list) {
    start.assign(nodes + 1, 0);
    for (int e = 0; e < items; ++e) {
      for (int i = 0; i < per_item; ++i) ++start[node_of(e, i) + 1];
    }
    for (int v = 0; v < nodes; ++v) start[v + 1] += start[v];
    list.resize(start[nodes]);
    std::vector<int> next(start.begin(), start.end() - 1);
    for (int e = 0; e < items; ++e) {
      for (int i = 0; i < per_item; ++i) list[next[node_of(e, i)]++] = e;
    }
  };
  build(
      static_cast<int>(mesh_.triangles.size()), m,
      [&](int e, int i) { return mesh_.triangles[e][i]; }, node_element_start_, node_elements_);
  build(
      static_cast<int>(robin_edges_.size()), edge_nodes,
      [&](int e, int i) { return robin_edges_[e].nodes[i]; }, node_edge_start_, node_edges_);
}

void Assembler::build_colouring() {
  // Greedy colouring of the chunks in order: a chunk takes the smallest colour that no earlier
  // chunk sharing a free dof with it has.
  const int elements = static_cast<int>(mesh_.triangles.size());
  const int chunks = (elements + kChunkElements - 1) / kChunkElements;
  const int m = mesh_.nodes_per_triangle();
  std::vector<int> colour(chunks, -1), seen_by;
  for (int c = 0; c < chunks; ++c) {
    for_chunk_elements(c, [&](int e) {
      for (int i = 0; i < m; ++i) {
        const int node = mesh_.triangles[e][i];
        if (dofs_.dof_of_node[node] < 0) continue;
        for (int s = node_element_start_[node]; s < node_element_start_[node + 1]; ++s) {
          const int other = colour[node_elements_[s] / kChunkElements];
          if (other < 0) continue;
          if (other >= static_cast<int>(seen_by.size())) seen_by.resize(other + 1, -1);
          seen_by[other] = c;
        }
      }
    });
    int k = 0;
    while (k < static_cast<int>(seen_by.size()) && seen_by[k] == c) ++k;
    colour[c] = k;
    if (k >= static_cast<int>(colour_chunks_.size())) colour_chunks_.resize(k + 1);
    colour_chunks_[k].push_back(c);
  }
}

template <class Visit>
void Assembler::for_chunk_elements(int chunk, Visit visit) const {
  const int end = std::min(static_cast<int>(mesh_.triangles.size()), (chunk + 1) * kChunkElements);
  for (int e = chunk * kChunkElements; e < end; ++e) visit(e);
}

int Assembler::matrix_offset(int row, int col) const {
  if (row < 0 || col < 0 || row < col) return -1;
  const int* begin = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[col];
  const int* end = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(begin, end, row);
  return it != end && *it == row ? static_cast<int>(it - pattern_.innerIndexPtr()) : -1;
}

void Assembler::quadrature(int e, ElementQuadrature& q) const {
  element_quadrature(problem_.symmetry, problem_.depth, mesh_.order, vertices(mesh_, e), q);
}

const ElementQuadrature& Assembler::geometry(int e, ElementQuadrature& scratch) const {
  if (!geometry_.empty()) return geometry_[e];
  quadrature(e, scratch);
  return scratch;
}

bool Assembler::nonlinear() const {
  return std::any_of(laws_.begin(), laws_.end(),
                     [](const Reluctivity& l) { return l.nonlinear(); });
}

void Assembler::build_linear_part() {
  const int elements = static_cast<int>(mesh_.triangles.size());
  const int m = mesh_.nodes_per_triangle();
  for (int e = 0; e < elements; ++e) linear_triangles_ += law(e).nonlinear() ? 0 : 1;
  if (linear_triangles_ == 0) return;
  // A linear triangle's residual is its tangent times its nodal values, at any state.
  linear_values_.assign(static_cast<std::size_t>(pattern_.nonZeros()), 0.0);
  std::vector<Eigen::Triplet<double, int>> prescribed;
  ElementQuadrature q;
  const double a_local[kMaxElementNodes] = {};
  double r_local[kMaxElementNodes], k_local[kMaxElementNodes * kMaxElementNodes];
  for (int e = 0; e < elements; ++e) {
    if (law(e).nonlinear()) continue;
    element_residual_tangent(geometry(e, q), a_local, law(e), r_local, k_local);
    const int* offsets = &element_offsets_[static_cast<std::size_t>(e) * m * m];
    for (int k = 0; k < m * m; ++k) {
      if (offsets[k] >= 0) linear_values_[offsets[k]] += k_local[k];
    }
    const auto& t = mesh_.triangles[e];
    for (int i = 0; i < m; ++i) {
      const int row = dofs_.dof_of_node[t[i]];
      if (row < 0) continue;
      for (int j = 0; j < m; ++j) {
        if (dofs_.dof_of_node[t[j]] < 0) prescribed.emplace_back(row, t[j], k_local[i * m + j]);
      }
    }
  }
  linear_prescribed_.resize(dofs_.free_count(), static_cast<int>(mesh_.nodes.size()));
  linear_prescribed_.setFromTriplets(prescribed.begin(), prescribed.end());
}

void Assembler::add_linear_part(const Eigen::VectorXd& a, Eigen::VectorXd& residual,
                                double* values) const {
  const int n = dofs_.free_count();
  const Eigen::Map<const SparseMatrix> k(n, n, pattern_.nonZeros(), pattern_.outerIndexPtr(),
                                         pattern_.innerIndexPtr(), linear_values_.data());
  Eigen::VectorXd a_free(n);
  for (int d = 0; d < n; ++d) a_free[d] = a[dofs_.node_of_dof[d]];
  residual.noalias() += k.selfadjointView<Eigen::Lower>() * a_free;
  residual.noalias() += linear_prescribed_ * a;
  if (values) std::copy(linear_values_.begin(), linear_values_.end(), values);
}

void Assembler::assemble(const Eigen::VectorXd& a, Eigen::VectorXd& residual, SparseMatrix* tangent,
                         ElementSet set) const {
  residual.setZero(dofs_.free_count());
  const int m = mesh_.nodes_per_triangle();
  const int elements = static_cast<int>(mesh_.triangles.size());
  double* values = tangent ? tangent->valuePtr() : nullptr;
  const std::ptrdiff_t nonzeros = tangent ? tangent->nonZeros() : 0;
  // The linear triangles come from their kept matrix; only the nonlinear ones are visited.
  const bool kept = linear_triangles_ > 0 && set != ElementSet::nonlinear;
  if (kept) add_linear_part(a, residual, values);
  const int team = assembly_team(elements, kChunkElements);
#pragma omp parallel num_threads(team) if (team > 1)
  {
    if (!kept) {
#pragma omp for schedule(static)
      for (std::ptrdiff_t k = 0; k < nonzeros; ++k) values[k] = 0.0;
    }
    ElementQuadrature q;
    double a_local[kMaxElementNodes], r_local[kMaxElementNodes];
    double k_local[kMaxElementNodes * kMaxElementNodes];
    for (const std::vector<int>& chunks : colour_chunks_) {
      // Chunks of one colour touch disjoint dofs: no two threads add to the same entry.
#pragma omp for schedule(dynamic, 1)
      for (std::size_t c = 0; c < chunks.size(); ++c) {
        for_chunk_elements(chunks[c], [&](int e) {
          const bool nonlinear = law(e).nonlinear();
          if ((kept && !nonlinear) || (set == ElementSet::linear && nonlinear) ||
              (set == ElementSet::nonlinear && !nonlinear))
            return;
          const auto& t = mesh_.triangles[e];
          for (int i = 0; i < m; ++i) a_local[i] = a[t[i]];
          element_residual_tangent(geometry(e, q), a_local, law(e), r_local,
                                   tangent ? k_local : nullptr);
          for (int i = 0; i < m; ++i) {
            const int row = dofs_.dof_of_node[t[i]];
            if (row >= 0) residual[row] += r_local[i];
          }
          if (!tangent) return;
          const int* offsets = &element_offsets_[static_cast<std::size_t>(e) * m * m];
          for (int k = 0; k < m * m; ++k) {
            if (offsets[k] >= 0) values[offsets[k]] += k_local[k];
          }
        });
      }
    }
  }
  if (set != ElementSet::nonlinear) scatter_robin(a, residual, tangent);
}

void Assembler::robin_local(const RobinEdge& edge, const Eigen::VectorXd& a, double* r_local,
                            double* k_local) const {
  const int edge_nodes = mesh_.order == 1 ? 2 : 3;
  std::fill_n(r_local, 3, 0.0);
  std::fill_n(k_local, 9, 0.0);
  for_robin_points(edge, [&](const double* n, double w) {
    double a_point = 0.0;
    for (int i = 0; i < edge_nodes; ++i) a_point += n[i] * a[edge.nodes[i]];
    for (int i = 0; i < edge_nodes; ++i) {
      r_local[i] += w * (edge.c0 * a_point - edge.c1) * n[i];
      for (int j = 0; j < edge_nodes; ++j) k_local[i * 3 + j] += w * edge.c0 * n[i] * n[j];
    }
  });
}

template <class Visit>
void Assembler::for_robin_points(const RobinEdge& edge, Visit visit) const {
  // Edge quadrature: visit(shape values, weight dw = 2 pi r ds or depth ds).
  const mesh::Point p0 = mesh_.nodes[edge.nodes[0]], p1 = mesh_.nodes[edge.nodes[1]];
  const double length = std::hypot(p1.r - p0.r, p1.z - p0.z);
  for (const EdgeQuadraturePoint& g : edge_quadrature()) {
    double n[3] = {0.0, 0.0, 0.0};
    edge_basis(mesh_.order, g.t, n);
    const double r = p0.r + g.t * (p1.r - p0.r);
    visit(n, g.weight * length *
                 (problem_.symmetry == cases::Symmetry::axisymmetric ? 2.0 * std::numbers::pi * r
                                                                     : problem_.depth));
  }
}

void Assembler::scatter_robin(const Eigen::VectorXd& a, Eigen::VectorXd& residual,
                              SparseMatrix* tangent) const {
  // Mixed condition  (n x H) . e_phi = c0 A - c1  (planar: nu dA/dn + c0 A = c1) adds
  // integral (c0 A - c1) v dw along the edge, dw = 2 pi r ds (axisymmetric) or depth ds.
  const int edge_nodes = mesh_.order == 1 ? 2 : 3;
  for (std::size_t k = 0; k < robin_edges_.size(); ++k) {
    const RobinEdge& edge = robin_edges_[k];
    double r_local[3], k_local[9];
    robin_local(edge, a, r_local, k_local);
    for (int i = 0; i < edge_nodes; ++i) {
      const int row = dofs_.dof_of_node[edge.nodes[i]];
      if (row >= 0) residual[row] += r_local[i];
    }
    if (!tangent) continue;
    for (int i = 0; i < 9; ++i) {
      const int offset = robin_offsets_[k * 9 + i];
      if (offset >= 0) tangent->valuePtr()[offset] += k_local[i];
    }
  }
}

double Assembler::edge_energy(const RobinEdge& edge, const Eigen::VectorXd& a) const {
  const int edge_nodes = mesh_.order == 1 ? 2 : 3;
  double energy = 0.0;
  for_robin_points(edge, [&](const double* n, double w) {
    double a_point = 0.0;
    for (int i = 0; i < edge_nodes; ++i) a_point += n[i] * a[edge.nodes[i]];
    energy += w * (0.5 * edge.c0 * a_point * a_point - edge.c1 * a_point);
  });
  return energy;
}

double Assembler::boundary_energy(const Eigen::VectorXd& a) const {
  double energy = 0.0;
  for (const RobinEdge& edge : robin_edges_) energy += edge_energy(edge, a);
  return energy;
}

Patch Assembler::patch(const std::vector<int>& seeds, int layers) const {
  const int m = mesh_.nodes_per_triangle();
  std::vector<char> in_patch(dofs_.free_count(), 0);
  Patch p;
  for (int d : seeds) {
    if (!in_patch[d]) p.dofs.push_back(d), in_patch[d] = 1;
  }
  std::size_t ring_begin = 0;
  for (int layer = 0; layer < layers; ++layer) {
    const std::size_t ring_end = p.dofs.size();
    for (std::size_t k = ring_begin; k < ring_end; ++k) {
      const int node = dofs_.node_of_dof[p.dofs[k]];
      for (int s = node_element_start_[node]; s < node_element_start_[node + 1]; ++s) {
        const auto& t = mesh_.triangles[node_elements_[s]];
        for (int i = 0; i < m; ++i) {
          const int d = dofs_.dof_of_node[t[i]];
          if (d >= 0 && !in_patch[d]) p.dofs.push_back(d), in_patch[d] = 1;
        }
      }
    }
    ring_begin = ring_end;
  }
  std::sort(p.dofs.begin(), p.dofs.end());
  std::vector<char> element_in(mesh_.triangles.size(), 0), edge_in(robin_edges_.size(), 0);
  for (int d : p.dofs) {
    const int node = dofs_.node_of_dof[d];
    for (int s = node_element_start_[node]; s < node_element_start_[node + 1]; ++s) {
      if (!element_in[node_elements_[s]]) p.elements.push_back(node_elements_[s]);
      element_in[node_elements_[s]] = 1;
    }
    for (int s = node_edge_start_[node]; s < node_edge_start_[node + 1]; ++s) {
      if (!edge_in[node_edges_[s]]) p.edges.push_back(node_edges_[s]);
      edge_in[node_edges_[s]] = 1;
    }
  }
  std::sort(p.elements.begin(), p.elements.end());
  std::sort(p.edges.begin(), p.edges.end());
  p.rows = p.dofs;
  auto add_row = [&](int node) {
    const int d = dofs_.dof_of_node[node];
    if (d >= 0 && !in_patch[d]) p.rows.push_back(d), in_patch[d] = 1;
  };
  for (int e : p.elements) {
    for (int i = 0; i < m; ++i) add_row(mesh_.triangles[e][i]);
  }
  const int edge_nodes = mesh_.order == 1 ? 2 : 3;
  for (int e : p.edges) {
    for (int i = 0; i < edge_nodes; ++i) add_row(robin_edges_[e].nodes[i]);
  }
  return p;
}

void Assembler::assemble_patch(const Patch& patch, const Eigen::VectorXd& a,
                               Eigen::VectorXd& residual, SparseMatrix* tangent) const {
  // Local row of each dof: patch.rows is short, a sorted search is cheap enough.
  std::vector<std::pair<int, int>> local(patch.rows.size());
  for (std::size_t k = 0; k < patch.rows.size(); ++k)
    local[k] = {patch.rows[k], static_cast<int>(k)};
  std::sort(local.begin(), local.end());
  auto row_of = [&](int node) {
    const int d = dofs_.dof_of_node[node];
    if (d < 0) return -1;
    return std::lower_bound(local.begin(), local.end(), std::pair<int, int>{d, -1})->second;
  };
  const int unknowns = static_cast<int>(patch.dofs.size());
  residual.setZero(static_cast<Eigen::Index>(patch.rows.size()));
  std::vector<Eigen::Triplet<double>> entries;
  auto scatter = [&](const int* row, int nodes, const double* r_local, const double* k_local,
                     int stride) {
    for (int i = 0; i < nodes; ++i) {
      if (row[i] < 0) continue;
      residual[row[i]] += r_local[i];
      if (!tangent || row[i] >= unknowns) continue;
      for (int j = 0; j < nodes; ++j) {
        if (row[j] >= 0 && row[j] <= row[i])
          entries.emplace_back(row[i], row[j], k_local[i * stride + j]);
      }
    }
  };
  const int m = mesh_.nodes_per_triangle();
  ElementQuadrature q;
  double a_local[kMaxElementNodes], r_local[kMaxElementNodes];
  double k_local[kMaxElementNodes * kMaxElementNodes];
  int row[kMaxElementNodes];
  for (int e : patch.elements) {
    const auto& t = mesh_.triangles[e];
    for (int i = 0; i < m; ++i) a_local[i] = a[t[i]], row[i] = row_of(t[i]);
    element_residual_tangent(geometry(e, q), a_local, law(e), r_local, tangent ? k_local : nullptr);
    scatter(row, m, r_local, k_local, m);
  }
  const int edge_nodes = mesh_.order == 1 ? 2 : 3;
  for (int k : patch.edges) {
    const RobinEdge& edge = robin_edges_[k];
    double re[3], ke[9];
    robin_local(edge, a, re, ke);
    for (int i = 0; i < edge_nodes; ++i) row[i] = row_of(edge.nodes[i]);
    scatter(row, edge_nodes, re, ke, 3);
  }
  if (tangent) {
    tangent->resize(unknowns, unknowns);
    tangent->setFromTriplets(entries.begin(), entries.end());
  }
}

double Assembler::patch_energy(const Patch& patch, const Eigen::VectorXd& a) const {
  const int m = mesh_.nodes_per_triangle();
  ElementQuadrature q;
  double a_local[kMaxElementNodes];
  double energy = 0.0;
  for (int e : patch.elements) {
    const auto& t = mesh_.triangles[e];
    for (int i = 0; i < m; ++i) a_local[i] = a[t[i]];
    energy += element_stored_energy(geometry(e, q), a_local, law(e));
  }
  for (int k : patch.edges) energy += edge_energy(robin_edges_[k], a);
  return energy;
}

double Assembler::energy(const Eigen::VectorXd& a) const {
  // Per-chunk sums added in chunk order: the same total for any number of threads.
  const int m = mesh_.nodes_per_triangle();
  const int elements = static_cast<int>(mesh_.triangles.size());
  const int chunks = (elements + kChunkElements - 1) / kChunkElements;
  std::vector<double> chunk_energy(chunks, 0.0);
  const int team = assembly_team(elements, kChunkElements);
#pragma omp parallel num_threads(team) if (team > 1)
  {
    ElementQuadrature q;
    double a_local[kMaxElementNodes];
#pragma omp for schedule(dynamic, 1)
    for (int c = 0; c < chunks; ++c) {
      for_chunk_elements(c, [&](int e) {
        const auto& t = mesh_.triangles[e];
        for (int i = 0; i < m; ++i) a_local[i] = a[t[i]];
        chunk_energy[c] += element_stored_energy(geometry(e, q), a_local, law(e));
      });
    }
  }
  double total = 0.0;
  for (double e : chunk_energy) total += e;
  return total + boundary_energy(a);
}

double Assembler::centroid_r(int e) const {
  const auto v = vertices(mesh_, e);
  return mesh::triangle_centroid(v[0], v[1], v[2]).r;
}

Eigen::VectorXd Assembler::circuit_source(int c) const {
  Eigen::VectorXd source = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh_.nodes.size()));
  const int m = mesh_.nodes_per_triangle();
  ElementQuadrature q;
  double f[kMaxElementNodes];
  for (int e = 0; e < static_cast<int>(mesh_.triangles.size()); ++e) {
    const int region = mesh_.region[e];
    const RegionCurrent& current = region_current_[region];
    if (problem_.regions[region].circuit != c || current.per_amp == 0.0) continue;
    quadrature(e, q);
    element_source(q, f);
    const double density = current.per_amp * current.g(centroid_r(e));
    const auto& t = mesh_.triangles[e];
    for (int i = 0; i < m; ++i) source[t[i]] += density * f[i];
  }
  return source;
}

SparseMatrix Assembler::region_matrix(const std::vector<double>& region_coefficient,
                                      bool curl) const {
  SparseMatrix matrix = pattern_;
  double* values = matrix.valuePtr();
  const int m = mesh_.nodes_per_triangle();
  ElementQuadrature q;
  for (int e = 0; e < static_cast<int>(mesh_.triangles.size()); ++e) {
    const double c = region_coefficient.at(mesh_.region[e]);
    if (c == 0.0) continue;
    quadrature(e, q);
    const int* offsets = &element_offsets_[static_cast<std::size_t>(e) * m * m];
    for (int p = 0; p < q.points; ++p) {
      const double w = c * q.weight[p];
      for (int i = 0; i < m; ++i) {
        for (int j = 0; j < m; ++j) {
          const int k = offsets[i * m + j];
          if (k < 0) continue;
          values[k] += w * (curl ? q.g_r[p][i] * q.g_r[p][j] + q.g_z[p][i] * q.g_z[p][j]
                                 : q.n[p][i] * q.n[p][j]);
        }
      }
    }
  }
  return matrix;
}

Eigen::VectorXd Assembler::fixed_source() const {
  Eigen::VectorXd source = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh_.nodes.size()));
  const int m = mesh_.nodes_per_triangle();
  std::vector<std::optional<cases::MagnetDirectionField>> directions(problem_.regions.size());
  ElementQuadrature q;
  double f[kMaxElementNodes];
  for (int e = 0; e < static_cast<int>(mesh_.triangles.size()); ++e) {
    const int region = mesh_.region[e];
    const cases::RegionData& data = problem_.regions[region];
    const double h_c = problem_.materials[data.material].coercivity;
    const double density =
        data.current_density + region_current_[region].density(0.0, centroid_r(e));
    if (density == 0.0 && h_c == 0.0) continue;
    quadrature(e, q);
    const auto& t = mesh_.triangles[e];
    if (density != 0.0) {
      element_source(q, f);
      for (int i = 0; i < m; ++i) source[t[i]] += density * f[i];
    }
    if (h_c == 0.0) continue;
    if (!directions[region]) {
      const auto& seeds = problem_.geometry.regions;
      const std::string name = region < static_cast<int>(seeds.size())
                                   ? seeds[region].name
                                   : "region " + std::to_string(region);
      directions[region].emplace(data.magnetisation,
                                 problem_.geometry.source + ": magnet '" + name + "'");
    }
    const auto v = vertices(mesh_, e);
    const mesh::Point centroid = mesh::triangle_centroid(v[0], v[1], v[2]);
    const double angle = directions[region]->degrees_at(centroid) * std::numbers::pi / 180.0;
    const double m_r = h_c * std::cos(angle), m_z = h_c * std::sin(angle);
    for (int p = 0; p < q.points; ++p) {
      for (int i = 0; i < m; ++i)
        source[t[i]] += q.weight[p] * (m_r * q.g_r[p][i] + m_z * q.g_z[p][i]);
    }
  }
  return source;
}

}  // namespace rheomag::magnetostatics
