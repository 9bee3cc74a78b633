#include "magnetostatics3d/report3d.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/constants.hpp"
#include "core/enum_names.hpp"
#include "mesh/vtu_writer.hpp"

namespace rheomag::magnetostatics3d {
namespace {

constexpr auto kGapKindNames = enum_names<mesh::GapKind>({{mesh::GapKind::none, "none"},
                                                          {mesh::GapKind::annular, "annular"},
                                                          {mesh::GapKind::radial, "radial"}});
constexpr auto kModelPartNames = enum_names<ModelPart>(
    {{ModelPart::wedge, "wedge"}, {ModelPart::half, "half"}, {ModelPart::full, "full"}});

/// A finite number, or JSON null (JSON has no NaN/inf).
nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

}  // namespace

nlohmann::json results_json_3d(const Results3d& results) {
  nlohmann::json gaps = nlohmann::json::array();
  for (const GapResult3d& g : results.gaps) {
    nlohmann::json theta = nlohmann::json::array();
    for (double b : g.b_avg_theta) theta.push_back(number(b));
    gaps.push_back({{"name", g.name},
                    {"kind", std::string(kGapKindNames.name(g.kind))},
                    {"B_avg", number(g.b.average)},
                    {"B_min", number(g.b.minimum)},
                    {"B_max", number(g.b.maximum)},
                    {"B_max_area", number(g.b.maximum)},  // docs/quantities.md: over the volume
                    {"Bn_avg", number(g.b_normal.average)},
                    {"Bn_min", number(g.b_normal.minimum)},
                    {"Bn_max", number(g.b_normal.maximum)},
                    {"volume", number(g.volume)},
                    {"B_avg_theta", theta}});
  }
  nlohmann::json circuits = nlohmann::json::array();
  for (const CircuitResult3d& c : results.circuits) {
    circuits.push_back({{"name", c.name},
                        {"current", number(c.current)},
                        {"flux_linkage", number(c.flux_linkage)},
                        {"inductance", number(c.inductance)}});
  }
  const bool has_circuit = !results.circuits.empty();
  return {
      {"dimension", 3},
      {"model", std::string(kModelPartNames.name(results.part))},
      {"span_degrees", results.span * 180.0 / std::numbers::pi},
      {"gaps", gaps},
      {"circuits", circuits},
      {"flux_linkage",
       has_circuit ? number(results.circuits.front().flux_linkage) : nlohmann::json()},
      {"inductance", has_circuit ? number(results.circuits.front().inductance) : nlohmann::json()},
      {"energy", number(results.energy)},
      {"newton_iterations", results.newton_iterations},
      {"linear_solver", std::string(kLinearSolver3dNames.name(results.linear_solver))},
      {"factorizations", results.factorizations},
      {"cg_iterations", results.cg_iterations},
      {"residual_history", results.residual_history},
      {"dofs", results.dofs},
      {"elements", results.tetrahedra},
      {"tetrahedra", results.tetrahedra},
      {"nodes", results.nodes},
      {"edges", results.edges},
      {"seconds", number(results.seconds)}};
}

std::string results_summary_3d(const Results3d& results) {
  std::ostringstream out;
  char line[512];
  const double residual = results.residual_history.empty() ? 0.0 : results.residual_history.back();
  std::snprintf(line, sizeof line,
                "3D magnetostatics (edge elements, %s model of %.1f degrees): %d tetrahedra, "
                "%d dofs, %d Newton iterations (final relative residual %.2e), %.2f s\n",
                std::string(kModelPartNames.name(results.part)).c_str(),
                results.span * 180.0 / std::numbers::pi, results.tetrahedra, results.dofs,
                results.newton_iterations, residual, results.seconds);
  out << line;
  if (!results.gaps.empty()) {
    out << "\nfluid gap [T]          kind        B_avg B_min_area B_max_area    Bn_avg\n";
    for (const GapResult3d& g : results.gaps) {
      std::snprintf(line, sizeof line, "  %-20.20s %-8s %8.3f %10.3f %10.3f %9.3f\n",
                    g.name.c_str(), std::string(kGapKindNames.name(g.kind)).c_str(), g.b.average,
                    g.b.minimum, g.b.maximum, g.b_normal.average);
      out << line;
      out << "    |B| per 10-degree sector from phi = 0:";
      for (int k = 0; k < kThetaSectors; ++k) {
        if (k % 12 == 0) out << "\n     ";
        std::snprintf(line, sizeof line, " %.3f", g.b_avg_theta[k]);
        out << line;
      }
      out << "\n";
    }
  }
  if (!results.circuits.empty()) {
    out << "\ncircuit               current [A]  lambda [mWb]  L=lambda/I [mH]\n";
    for (const CircuitResult3d& c : results.circuits) {
      std::snprintf(line, sizeof line, "  %-20.20s %11.4g %13.5g %16.5g\n", c.name.c_str(),
                    c.current, c.flux_linkage * 1e3, c.inductance * 1e3);
      out << line;
    }
  }
  std::snprintf(line, sizeof line, "\nstored energy %.6g J\n", results.energy);
  out << line;
  return out.str();
}

void write_results_vtu_3d(const std::string& path, const Solve3dResult& solved) {
  const TetMesh& m = *solved.mesh;
  mesh::VtuGrid grid;
  grid.cell_type = 10;  // VTK_TETRA
  grid.nodes_per_cell = 4;
  for (const Eigen::Vector3d& x : m.nodes) grid.points.push_back({x[0], x[1], x[2]});
  for (const auto& t : m.tets)
    grid.connectivity.insert(grid.connectivity.end(), t.begin(), t.end());
  grid.region = m.region;
  std::vector<std::array<double, 3>> b(m.tets.size()), h(m.tets.size());
  std::vector<double> b_norm(m.tets.size()), mu_r(m.tets.size());
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    const Eigen::Vector3d& bt = solved.solution.b[t];
    const double nu = solved.solver->law(static_cast<int>(t)).nu(bt.squaredNorm());
    b[t] = {bt[0], bt[1], bt[2]};
    h[t] = {nu * bt[0], nu * bt[1], nu * bt[2]};
    b_norm[t] = bt.norm();
    mu_r[t] = 1.0 / (kMu0 * nu);
  }
  mesh::VtuFields fields;
  fields.add_cell_vector("B", b);
  fields.add_cell_scalar("B_magnitude", b_norm);
  fields.add_cell_vector("H", h);
  fields.add_cell_scalar("mu_r", mu_r);
  std::vector<std::string> names;
  for (const auto& region : solved.closed.geometry.regions) names.push_back(region.name);
  mesh::write_vtu(path, grid, fields, names);
}

}  // namespace rheomag::magnetostatics3d
