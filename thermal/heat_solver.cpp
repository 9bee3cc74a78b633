// Heat conduction on the magnetic mesh: assembly of conduction, capacity and convection, the
// steady solve and the BDF2 transient, and the heat balance of a field.

#include "thermal/heat_solver.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <utility>

#include "core/error.hpp"
#include "core/format_text.hpp"
#include "magnetostatics/cholmod_status.hpp"
#include "magnetostatics/lagrange.hpp"
#include "magnetostatics/serial_openmp.hpp"

namespace rheomag::thermal {

namespace {

namespace ms = magnetostatics;
using Triplets = std::vector<Eigen::Triplet<double>>;

/// Local node pairs of a triangle's edges and the edge's midpoint node (P2).
constexpr std::array<std::array<int, 3>, 3> kTriangleEdges{{{0, 1, 3}, {1, 2, 4}, {2, 0, 5}}};

/// dV per unit area at radius r: 2 pi r (axisymmetric) or the depth (planar).
double volume_weight(const cases::Problem& problem, double r) {
  return problem.symmetry == cases::Symmetry::axisymmetric ? 2.0 * std::numbers::pi * r
                                                           : problem.depth;
}

/// One triangle's conduction (k = 1) and capacity (rho c = 1) matrices and its source vector
/// (q = 1), row-major nodes x nodes.
struct ElementMatrices {
  int nodes = 3;
  std::array<double, 36> conduction{}, capacity{};
  std::array<double, 6> source{};
  double volume = 0.0;
};

ElementMatrices element_matrices(const cases::Problem& problem, const mesh::Mesh& mesh, int e) {
  ElementMatrices m;
  m.nodes = mesh.nodes_per_triangle();
  const auto& t = mesh.triangles[e];
  const mesh::Point v0 = mesh.nodes[t[0]], v1 = mesh.nodes[t[1]], v2 = mesh.nodes[t[2]];
  const double r10 = v1.r - v0.r, r20 = v2.r - v0.r, z10 = v1.z - v0.z, z20 = v2.z - v0.z;
  const double det = r10 * z20 - r20 * z10;
  const double area = 0.5 * std::abs(det);
  for (const ms::TriangleQuadraturePoint& p : ms::triangle_quadrature(mesh.order)) {
    double n[ms::kMaxElementNodes], d_xi[ms::kMaxElementNodes], d_eta[ms::kMaxElementNodes];
    ms::lagrange_basis(mesh.order, p.xi, p.eta, n, d_xi, d_eta);
    const double r = v0.r + p.xi * r10 + p.eta * r20;
    const double w = area * p.weight * volume_weight(problem, r);
    m.volume += w;
    double dr[ms::kMaxElementNodes], dz[ms::kMaxElementNodes];
    for (int i = 0; i < m.nodes; ++i) {
      dr[i] = (z20 * d_xi[i] - z10 * d_eta[i]) / det;
      dz[i] = (-r20 * d_xi[i] + r10 * d_eta[i]) / det;
    }
    for (int i = 0; i < m.nodes; ++i) {
      m.source[i] += w * n[i];
      for (int j = 0; j < m.nodes; ++j) {
        m.conduction[i * m.nodes + j] += w * (dr[i] * dr[j] + dz[i] * dz[j]);
        m.capacity[i * m.nodes + j] += w * n[i] * n[j];
      }
    }
  }
  return m;
}

/// Calls visit(value of the edge shape functions, dA weight) at each Gauss point of an edge.
template <class Visit>
void for_edge_points(const cases::Problem& problem, const mesh::Mesh& mesh,
                     const std::array<int, 3>& nodes, Visit visit) {
  const mesh::Point a = mesh.nodes[nodes[0]], b = mesh.nodes[nodes[1]];
  const double length = std::hypot(b.r - a.r, b.z - a.z);
  for (const ms::EdgeQuadraturePoint& p : ms::edge_quadrature()) {
    double value[3] = {0.0, 0.0, 0.0};
    ms::edge_basis(mesh.order, p.t, value);
    const double r = a.r + p.t * (b.r - a.r);
    visit(value, length * p.weight * volume_weight(problem, r));
  }
}

int edge_nodes(const mesh::Mesh& mesh) {
  return mesh.order == 1 ? 2 : 3;
}

}  // namespace

std::vector<double> region_volumes(const cases::Problem& problem, const mesh::Mesh& mesh) {
  std::vector<double> volume(problem.regions.size(), 0.0);
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e)
    volume[mesh.region[e]] += element_matrices(problem, mesh, static_cast<int>(e)).volume;
  return volume;
}

double temperature_at(const mesh::Mesh& mesh, const Eigen::VectorXd& temperature, mesh::Point p) {
  const int per = mesh.nodes_per_triangle();
  for (const auto& t : mesh.triangles) {
    const mesh::Point v0 = mesh.nodes[t[0]], v1 = mesh.nodes[t[1]], v2 = mesh.nodes[t[2]];
    const double r10 = v1.r - v0.r, r20 = v2.r - v0.r, z10 = v1.z - v0.z, z20 = v2.z - v0.z;
    const double det = r10 * z20 - r20 * z10;
    const double xi = ((p.r - v0.r) * z20 - (p.z - v0.z) * r20) / det;
    const double eta = (r10 * (p.z - v0.z) - z10 * (p.r - v0.r)) / det;
    constexpr double kSlack = -1e-12;
    if (xi < kSlack || eta < kSlack || xi + eta > 1.0 - kSlack) continue;
    double n[ms::kMaxElementNodes], d_xi[ms::kMaxElementNodes], d_eta[ms::kMaxElementNodes];
    ms::lagrange_basis(mesh.order, xi, eta, n, d_xi, d_eta);
    double value = 0.0;
    for (int i = 0; i < per; ++i) value += n[i] * temperature[t[i]];
    return value;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double HeatSolution::balance_error() const {
  double out = storage_power + exchange_heat_flow;
  for (double flow : surface_heat_flow) out += flow;
  const double scale = std::max(std::abs(source_power), 1.0);
  return (source_power - out) / scale;
}

HeatSolver::~HeatSolver() = default;

HeatSolver::HeatSolver(const cases::Problem& problem, const mesh::Mesh& mesh, HeatModel model)
    : problem_(problem), mesh_(mesh), model_(std::move(model)) {
  if (model_.regions.size() != problem_.regions.size() ||
      model_.surface_of_region.size() != problem_.regions.size())
    throw InputError("thermal model: one entry per region expected");
  bool any = false;
  for (std::size_t r = 0; r < model_.regions.size(); ++r) {
    const HeatRegion& region = model_.regions[r];
    if (!region.active) continue;
    any = true;
    const std::string& name = problem_.geometry.regions[r].name;
    if (!(region.conductivity > 0.0) || !std::isfinite(region.conductivity))
      throw InputError(
          format_text("thermal model: region '%s': conductivity must be > 0 W/(m K), "
                      "got %.6g",
                      name.c_str(), region.conductivity));
    if (!(region.heat_capacity > 0.0) || !std::isfinite(region.heat_capacity))
      throw InputError(
          format_text("thermal model: region '%s': heat capacity must be > 0 "
                      "J/(m^3 K), got %.6g",
                      name.c_str(), region.heat_capacity));
    const int s = model_.surface_of_region[r];
    if (s < 0 || s >= static_cast<int>(model_.surfaces.size()))
      throw InputError("thermal model: region '" + name + "' has no surface condition");
  }
  if (!any)
    throw InputError(
        "thermal model: no region has thermal data (every material is "
        "outside the thermal model)");
  active_of_node_.assign(mesh_.nodes.size(), -1);
  const int per = mesh_.nodes_per_triangle();
  for (std::size_t e = 0; e < mesh_.triangles.size(); ++e) {
    if (!model_.regions[mesh_.region[e]].active) continue;
    for (int i = 0; i < per; ++i) {
      const int node = mesh_.triangles[e][i];
      if (active_of_node_[node] < 0) {
        active_of_node_[node] = static_cast<int>(node_of_active_.size());
        node_of_active_.push_back(node);
      }
    }
  }
  find_outer_edges();
  assemble();
}

void HeatSolver::find_outer_edges() {
  // An edge (its two vertices) shared by two active triangles is inside the model.
  std::map<std::pair<int, int>, std::pair<int, int>> count;  // edge -> (triangles, last one)
  for (std::size_t e = 0; e < mesh_.triangles.size(); ++e) {
    if (!model_.regions[mesh_.region[e]].active) continue;
    for (const auto& edge : kTriangleEdges) {
      const int a = mesh_.triangles[e][edge[0]], b = mesh_.triangles[e][edge[1]];
      auto& entry = count[{std::min(a, b), std::max(a, b)}];
      ++entry.first;
      entry.second = static_cast<int>(e);
    }
  }
  std::map<std::pair<int, int>, int> marker;  // boundary-marked mesh edges -> their surface
  for (const mesh::BoundaryEdge& edge : mesh_.boundary_edges) {
    const int b = edge.boundary;
    if (b < 0 || b >= static_cast<int>(model_.surface_of_boundary.size())) continue;
    const int surface = model_.surface_of_boundary[b];
    if (surface < 0) continue;
    if (surface >= static_cast<int>(model_.surfaces.size()))
      throw InputError("thermal model: boundary surface index out of range");
    marker[{std::min(edge.nodes[0], edge.nodes[1]), std::max(edge.nodes[0], edge.nodes[1])}] =
        surface;
  }
  double extent = 0.0;
  for (const mesh::Point& p : mesh_.nodes)
    extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
  const double on_axis = 1e-9 * std::max(extent, 1e-300);
  const bool axisymmetric = problem_.symmetry == cases::Symmetry::axisymmetric;
  fixed_surface_of_active_.assign(node_of_active_.size(), -1);
  for (std::size_t e = 0; e < mesh_.triangles.size(); ++e) {
    if (!model_.regions[mesh_.region[e]].active) continue;
    for (const auto& edge : kTriangleEdges) {
      const int a = mesh_.triangles[e][edge[0]], b = mesh_.triangles[e][edge[1]];
      if (count[{std::min(a, b), std::max(a, b)}].first != 1) continue;
      if (axisymmetric && std::abs(mesh_.nodes[a].r) <= on_axis &&
          std::abs(mesh_.nodes[b].r) <= on_axis)
        continue;  // the axis: symmetry
      OuterEdge outer;
      outer.nodes = {a, b, mesh_.order == 2 ? mesh_.triangles[e][edge[2]] : -1};
      const auto marked = marker.find({std::min(a, b), std::max(a, b)});
      outer.surface =
          marked != marker.end() ? marked->second : model_.surface_of_region[mesh_.region[e]];
      const SurfaceCondition& s = model_.surfaces[outer.surface];
      if (s.kind == SurfaceKind::insulated) continue;
      if (s.kind == SurfaceKind::fixed_temperature)
        for (int i = 0; i < edge_nodes(mesh_); ++i) {
          int& fixed = fixed_surface_of_active_[active_of_node_[outer.nodes[i]]];
          if (fixed < 0) fixed = outer.surface;
        }
      outer_edges_.push_back(outer);
    }
  }
  free_of_active_.assign(node_of_active_.size(), -1);
  for (std::size_t i = 0; i < node_of_active_.size(); ++i)
    if (fixed_surface_of_active_[i] < 0) {
      free_of_active_[i] = static_cast<int>(node_of_free_.size());
      node_of_free_.push_back(node_of_active_[i]);
    }
  bool level = false;
  for (const OuterEdge& edge : outer_edges_) {
    const SurfaceCondition& s = model_.surfaces[edge.surface];
    if (s.kind == SurfaceKind::fixed_temperature || s.h > 0.0) level = true;
  }
  for (const HeatRegion& region : model_.regions)
    if (region.active && region.exchange > 0.0) level = true;
  if (!level)
    throw InputError(
        "thermal model: every outer surface is insulated (or has h = 0): there is "
        "no steady temperature; give a convection coefficient > 0 or a fixed "
        "temperature somewhere");
}

void HeatSolver::assemble() {
  const int n = static_cast<int>(node_of_active_.size());
  Triplets k, m;
  region_load_.assign(model_.regions.size(), Eigen::VectorXd());
  exchange_load_ = Eigen::VectorXd::Zero(n);
  for (std::size_t e = 0; e < mesh_.triangles.size(); ++e) {
    const int region = mesh_.region[e];
    const HeatRegion& data = model_.regions[region];
    if (!data.active) continue;
    const ElementMatrices local = element_matrices(problem_, mesh_, static_cast<int>(e));
    Eigen::VectorXd& load = region_load_[region];
    if (load.size() == 0) load = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < local.nodes; ++i) {
      const int row = active_of_node_[mesh_.triangles[e][i]];
      load[row] += local.source[i];
      exchange_load_[row] += data.exchange * data.exchange_temperature * local.source[i];
      for (int j = 0; j < local.nodes; ++j) {
        const int col = active_of_node_[mesh_.triangles[e][j]];
        k.emplace_back(row, col,
                       data.conductivity * local.conduction[i * local.nodes + j] +
                           data.exchange * local.capacity[i * local.nodes + j]);
        m.emplace_back(row, col, data.heat_capacity * local.capacity[i * local.nodes + j]);
      }
    }
  }
  convection_load_ = Eigen::VectorXd::Zero(n);
  const int en = edge_nodes(mesh_);
  for (const OuterEdge& edge : outer_edges_) {
    const SurfaceCondition& s = model_.surfaces[edge.surface];
    if (s.kind != SurfaceKind::convection) continue;
    for_edge_points(problem_, mesh_, edge.nodes, [&](const double* value, double w) {
      for (int i = 0; i < en; ++i) {
        const int row = active_of_node_[edge.nodes[i]];
        convection_load_[row] += w * s.h * s.ambient * value[i];
        for (int j = 0; j < en; ++j)
          k.emplace_back(row, active_of_node_[edge.nodes[j]], w * s.h * value[i] * value[j]);
      }
    });
  }
  stiffness_.resize(n, n);
  stiffness_.setFromTriplets(k.begin(), k.end());
  mass_.resize(n, n);
  mass_.setFromTriplets(m.begin(), m.end());
  // Free-free blocks and the free-fixed coupling.
  const int nf = unknowns();
  Triplets kf, mf, kc;
  for (int col = 0; col < n; ++col) {
    for (Matrix::InnerIterator it(stiffness_, col); it; ++it) {
      const int fr = free_of_active_[it.row()], fc = free_of_active_[col];
      if (fr >= 0 && fc >= 0) kf.emplace_back(fr, fc, it.value());
      if (fr >= 0 && fc < 0) kc.emplace_back(fr, col, it.value());
    }
    for (Matrix::InnerIterator it(mass_, col); it; ++it) {
      const int fr = free_of_active_[it.row()], fc = free_of_active_[col];
      if (fr >= 0 && fc >= 0) mf.emplace_back(fr, fc, it.value());
    }
  }
  stiffness_free_.resize(nf, nf);
  stiffness_free_.setFromTriplets(kf.begin(), kf.end());
  mass_free_.resize(nf, nf);
  mass_free_.setFromTriplets(mf.begin(), mf.end());
  stiffness_coupling_.resize(nf, n);
  stiffness_coupling_.setFromTriplets(kc.begin(), kc.end());
}

void HeatSolver::set_sources(const std::vector<double>& region_source) {
  if (region_source.size() != model_.regions.size())
    throw InputError("thermal model: one heat source per region expected");
  for (std::size_t r = 0; r < region_source.size(); ++r) {
    if (!std::isfinite(region_source[r]))
      throw ConvergenceError("thermal model: the heat source of region '" +
                             problem_.geometry.regions[r].name + "' is not finite");
    if (region_source[r] != 0.0 && !model_.regions[r].active)
      throw InputError("thermal model: region '" + problem_.geometry.regions[r].name +
                       "' has a heat source but no thermal data");
    model_.regions[r].source = region_source[r];
  }
}

Eigen::VectorXd HeatSolver::load() const {
  Eigen::VectorXd f = convection_load_ + exchange_load_;
  for (std::size_t r = 0; r < model_.regions.size(); ++r)
    if (model_.regions[r].source != 0.0 && region_load_[r].size() > 0)
      f += model_.regions[r].source * region_load_[r];
  return f;
}

Eigen::VectorXd HeatSolver::fixed_values() const {
  Eigen::VectorXd t = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(node_of_active_.size()));
  for (std::size_t i = 0; i < node_of_active_.size(); ++i)
    if (fixed_surface_of_active_[i] >= 0)
      t[i] = model_.surfaces[fixed_surface_of_active_[i]].temperature;
  return t;
}

Eigen::VectorXd HeatSolver::to_nodes(const Eigen::VectorXd& free_values) const {
  Eigen::VectorXd t = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(mesh_.nodes.size()),
                                                std::numeric_limits<double>::quiet_NaN());
  const Eigen::VectorXd fixed = fixed_values();
  for (std::size_t i = 0; i < node_of_active_.size(); ++i)
    t[node_of_active_[i]] = free_of_active_[i] >= 0 ? free_values[free_of_active_[i]] : fixed[i];
  return t;
}

Eigen::VectorXd HeatSolver::uniform(double celsius) const {
  Eigen::VectorXd free = Eigen::VectorXd::Constant(unknowns(), celsius);
  return to_nodes(free);
}

HeatSolver::Factor& HeatSolver::factor_for(double mass_scale) {
  if (factor_ && factor_scale_ == mass_scale) return *factor_;
  // CHOLMOD's OpenMP regions on this thread, inline, as in the magnetic solver: its compiled-in
  // teams of 4 threads wait at barriers on a 2-core machine (docs/performance.md, round 3 and 5).
  const magnetostatics::SerialOpenMp serial;
  const Matrix system =
      mass_scale == 0.0 ? stiffness_free_ : Matrix(stiffness_free_ + mass_scale * mass_free_);
  if (!factor_) {
    factor_ = std::make_unique<Factor>();
    factor_->analyzePattern(system);  // the pattern is the same for every scale
  }
  factor_->factorize(system);
  magnetostatics::throw_if_out_of_memory(*factor_);
  if (factor_->info() != Eigen::Success)
    throw ConvergenceError("thermal model: the conduction matrix is not positive definite");
  factor_scale_ = mass_scale;
  return *factor_;
}

Eigen::VectorXd HeatSolver::free_load() const {
  Eigen::VectorXd rhs(unknowns());
  const Eigen::VectorXd f = load();
  for (int i = 0; i < static_cast<int>(node_of_active_.size()); ++i)
    if (free_of_active_[i] >= 0) rhs[free_of_active_[i]] = f[i];
  return rhs - stiffness_coupling_ * fixed_values();
}

HeatSolution HeatSolver::steady() {
  const Eigen::VectorXd t = factor_for(0.0).solve(free_load());
  return evaluate(to_nodes(t), Eigen::VectorXd());
}

HeatSolution HeatSolver::transient(const Eigen::VectorXd& initial, double dt, int steps,
                                   const Observer& observe) {
  if (!(dt > 0.0) || !std::isfinite(dt) || steps < 1)
    throw InputError(
        format_text("thermal transient: needs a time step > 0 and at least one "
                    "step (got %.6g s, %d)",
                    dt, steps));
  if (initial.size() != static_cast<Eigen::Index>(mesh_.nodes.size()))
    throw InputError("thermal transient: one initial temperature per mesh node expected");
  Eigen::VectorXd current(unknowns());
  for (int i = 0; i < unknowns(); ++i) current[i] = initial[node_of_free_[i]];
  if (!current.allFinite())
    throw InputError("thermal transient: the initial temperature is not finite on the model");
  HeatSolution state = evaluate(to_nodes(current), Eigen::VectorXd());
  state.storage_power = state.source_power;
  for (double flow : state.surface_heat_flow) state.storage_power -= flow;
  if (observe && !observe(state)) return state;
  Eigen::VectorXd previous = current;
  for (int step = 1; step <= steps; ++step) {
    const Eigen::VectorXd rhs_fixed = free_load();  // the observer may have changed the sources
    Eigen::VectorXd next, rate;
    if (step == 1) {  // backward Euler: (K + M/dt) T1 = f + M T0 / dt
      next = factor_for(1.0 / dt).solve(rhs_fixed + mass_free_ * current / dt);
      rate = (next - current) / dt;
    } else {  // BDF2: (K + 3M/(2dt)) T = f + M (4 T_n - T_n-1) / (2 dt)
      next = factor_for(1.5 / dt).solve(rhs_fixed +
                                        mass_free_ * (4.0 * current - previous) / (2.0 * dt));
      rate = (3.0 * next - 4.0 * current + previous) / (2.0 * dt);
    }
    if (!next.allFinite())
      throw ConvergenceError(
          format_text("thermal transient: non-finite temperature at step %d", step));
    previous = current;
    current = next;
    Eigen::VectorXd rate_nodes =
        Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh_.nodes.size()));
    for (int i = 0; i < unknowns(); ++i) rate_nodes[node_of_free_[i]] = rate[i];
    state = evaluate(to_nodes(current), rate_nodes);
    state.time = step * dt;
    if (observe && !observe(state)) break;
  }
  return state;
}

HeatSolution HeatSolver::evaluate(const Eigen::VectorXd& temperature,
                                  const Eigen::VectorXd& rate) const {
  HeatSolution s;
  s.temperature = temperature;
  const int n = static_cast<int>(node_of_active_.size());
  Eigen::VectorXd t(n), tdot = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i) {
    t[i] = temperature[node_of_active_[i]];
    if (rate.size() > 0) tdot[i] = rate[node_of_active_[i]];
  }
  s.regions.assign(model_.regions.size(), RegionTemperature{});
  std::vector<double> weighted(model_.regions.size(), 0.0);
  for (std::size_t r = 0; r < model_.regions.size(); ++r) {
    if (region_load_[r].size() == 0) continue;
    // region_load_ = integral N_i dV: its sum is the volume, its dot with T the integral of T.
    s.regions[r].volume = region_load_[r].sum();
    s.regions[r].mean = region_load_[r].dot(t) / s.regions[r].volume;
    s.regions[r].max = -std::numeric_limits<double>::infinity();
    s.source_power += model_.regions[r].source * s.regions[r].volume;
    s.exchange_heat_flow +=
        model_.regions[r].exchange *
        (region_load_[r].dot(t) - model_.regions[r].exchange_temperature * s.regions[r].volume);
  }
  const int per = mesh_.nodes_per_triangle();
  for (std::size_t e = 0; e < mesh_.triangles.size(); ++e) {
    const int r = mesh_.region[e];
    if (!model_.regions[r].active) continue;
    for (int i = 0; i < per; ++i)
      s.regions[r].max = std::max(s.regions[r].max, temperature[mesh_.triangles[e][i]]);
  }
  s.surface_heat_flow.assign(model_.surfaces.size(), 0.0);
  const int en = edge_nodes(mesh_);
  for (const OuterEdge& edge : outer_edges_) {
    const SurfaceCondition& cond = model_.surfaces[edge.surface];
    if (cond.kind != SurfaceKind::convection) continue;
    for_edge_points(problem_, mesh_, edge.nodes, [&](const double* value, double w) {
      double at = 0.0;
      for (int i = 0; i < en; ++i) at += value[i] * temperature[edge.nodes[i]];
      s.surface_heat_flow[edge.surface] += w * cond.h * (at - cond.ambient);
    });
  }
  // Fixed-temperature surfaces: the heat leaving through them is what their rows leave over,
  // f - K T - M dT/dt (the free rows are zero; their sum over all rows is the balance).
  const Eigen::VectorXd leaving = load() - stiffness_ * t - mass_ * tdot;
  for (int i = 0; i < n; ++i)
    if (fixed_surface_of_active_[i] >= 0)
      s.surface_heat_flow[fixed_surface_of_active_[i]] += leaving[i];
  s.storage_power = (mass_ * tdot).sum();
  return s;
}

std::vector<double> HeatSolver::region_heat_capacity() const {
  std::vector<double> c(model_.regions.size(), 0.0);
  for (std::size_t r = 0; r < model_.regions.size(); ++r)
    if (region_load_[r].size() > 0) c[r] = model_.regions[r].heat_capacity * region_load_[r].sum();
  return c;
}

}  // namespace rheomag::thermal
