#include "magnetostatics/report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "mesh/vtu_writer.hpp"

namespace rheomag::magnetostatics {

namespace {

const char* gap_kind_name(mesh::GapKind kind) {
  switch (kind) {
    case mesh::GapKind::annular:
      return "annular";
    case mesh::GapKind::radial:
      return "radial";
    case mesh::GapKind::none:
      break;
  }
  return "none";
}

/// A finite number, or JSON null (JSON has no NaN/inf).
nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

nlohmann::json stats_json(const FieldStats& s) {
  return {{"average", number(s.average)}, {"min", number(s.minimum)}, {"max", number(s.maximum)}};
}

/// A gap line's samples: {"s": [m], "B_n": [T], "B_t": [T]}.
nlohmann::json profile_json(const GapProfile& p) {
  auto numbers = [](const std::vector<double>& v) {
    nlohmann::json a = nlohmann::json::array();
    for (double x : v) a.push_back(number(x));
    return a;
  };
  return {{"s", numbers(p.s)}, {"B_n", numbers(p.b_n)}, {"B_t", numbers(p.b_t)}};
}

std::vector<std::array<double, 3>> as_vectors(const std::vector<double>& x,
                                              const std::vector<double>& y) {
  std::vector<std::array<double, 3>> v(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) v[i] = {x[i], y[i], 0.0};
  return v;
}

}  // namespace

nlohmann::json results_json(const MagnetostaticSolver& solver, const Results& results) {
  nlohmann::json gaps = nlohmann::json::array();
  for (const GapResult& g : results.gaps) {
    // The names of docs/quantities.md: B_avg (area average), B_max_midline (along the gap's
    // mid-line), B_max_area (over the area: at the pole corners, where the field is singular and
    // grows with refinement). B_max / B_min (mid-line) and B_area_max / B_area_min are the same
    // values under the keys other tools already read (issue 2's fixed interface).
    gaps.push_back({{"name", g.name},
                    {"kind", gap_kind_name(g.kind)},
                    {"B_avg", number(g.b.average)},
                    {"B_max_midline", number(g.line_b.maximum)},
                    {"B_max_area", number(g.b.maximum)},
                    {"B_max", number(g.line_b.maximum)},
                    {"B_min", number(g.line_b.minimum)},
                    {"B_area_max", number(g.b.maximum)},
                    {"B_area_min", number(g.b.minimum)},
                    {"Bn_avg", number(g.b_normal.average)},
                    {"Bn_max", number(g.line_b_normal.maximum)},
                    {"Bn_min", number(g.line_b_normal.minimum)},
                    {"midline",
                     {{"B", stats_json(g.line_b)},
                      {"Bn", stats_json(g.line_b_normal)},
                      {"samples", g.line_samples}}},
                    {"profile",
                     [&g] {
                       nlohmann::json p = profile_json(g.profile);
                       p["walls"] = {profile_json(g.walls[0]), profile_json(g.walls[1])};
                       return p;
                     }()},
                    {"area", number(g.area)}});
  }
  nlohmann::json circuits = nlohmann::json::array();
  for (const CircuitResult& c : results.circuits) {
    circuits.push_back({{"name", c.name},
                        {"current", number(c.current)},
                        {"turns", number(c.turns)},
                        {"flux_linkage", number(c.flux_linkage)},
                        {"inductance", number(c.inductance)},
                        {"incremental_inductance", number(c.incremental_inductance)},
                        {"gauge_free", c.gauge_free}});
    if (!c.warning.empty()) circuits.back()["warning"] = c.warning;
  }
  const bool has_circuit = !results.circuits.empty();
  const CircuitResult first = has_circuit ? results.circuits.front() : CircuitResult{};
  const double nan = std::nan("");
  return {{"gaps", gaps},
          {"circuits", circuits},
          {"flux_linkage", number(has_circuit ? first.flux_linkage : nan)},
          {"inductance", number(has_circuit ? first.inductance : nan)},
          {"incremental_inductance", number(has_circuit ? first.incremental_inductance : nan)},
          {"energy", number(results.energy)},
          {"coenergy", number(results.coenergy)},
          {"newton_iterations", results.newton_iterations},
          {"residual_history", results.residual_history},
          {"dofs", results.dofs},
          {"elements", results.elements},
          {"nodes", results.nodes},
          {"order", solver.mesh().order},
          {"symmetry",
           solver.problem().symmetry == cases::Symmetry::axisymmetric ? "axisymmetric" : "planar"},
          {"seconds", number(results.seconds)}};
}

std::string results_summary(const MagnetostaticSolver& solver, const Results& results) {
  std::ostringstream out;
  char line[512];
  const double residual = results.residual_history.empty() ? 0.0 : results.residual_history.back();
  std::snprintf(
      line, sizeof line,
      "%s magnetostatics, P%d: %d elements, %d dofs, %d Newton iterations "
      "(final relative residual %.2e), %.3f s\n",
      solver.problem().symmetry == cases::Symmetry::axisymmetric ? "axisymmetric" : "planar",
      solver.mesh().order, results.elements, results.dofs, results.newton_iterations, residual,
      results.seconds);
  out << line;
  if (!results.gaps.empty()) {
    // Column names as docs/quantities.md defines them (the same in JSON and the sweep CSV).
    out << "\nfluid gap [T]          kind         B_avg    Bn_avg  B_min_midline  B_max_midline"
           "  B_max_area\n";
    for (const GapResult& g : results.gaps) {
      std::snprintf(line, sizeof line, "  %-20.20s %-8s %9.3f %9.3f %14.3f %14.3f %11.3f\n",
                    g.name.c_str(), gap_kind_name(g.kind), g.b.average, g.b_normal.average,
                    g.line_b.minimum, g.line_b.maximum, g.b.maximum);
      out << line;
    }
  }
  if (!results.circuits.empty()) {
    out << "\ncircuit               current [A]   turns  lambda [mWb]  L=lambda/I [mH]  "
           "dlambda/dI [mH]\n";
    for (const CircuitResult& c : results.circuits) {
      if (!c.gauge_free) {
        std::snprintf(line, sizeof line,
                      "  %-20.20s %11.4g %7.0f  not gauge-free (one-sided circuit in a model "
                      "without prescribed A)\n",
                      c.name.c_str(), c.current, c.turns);
        out << line;
        continue;
      }
      std::snprintf(line, sizeof line, "  %-20.20s %11.4g %7.0f %13.5g %16.5g %16.5g\n",
                    c.name.c_str(), c.current, c.turns, c.flux_linkage * 1e3, c.inductance * 1e3,
                    c.incremental_inductance * 1e3);
      out << line;
      if (!c.warning.empty()) out << "    warning: " << c.warning << "\n";
    }
  }
  std::snprintf(line, sizeof line, "\nstored energy %.6g J, co-energy %.6g J\n", results.energy,
                results.coenergy);
  out << line;
  return out.str();
}

void write_results_vtu(const std::string& path, const MagnetostaticSolver& solver,
                       const Solution& solution, const Results& results,
                       const mesh::VtuFields& extra) {
  const mesh::Mesh& m = solver.mesh();
  mesh::VtuFields fields;
  fields.add_point_scalar(
      "A", std::vector<double>(solution.a.data(), solution.a.data() + solution.a.size()));
  fields.add_cell_vector("B", as_vectors(results.element_br, results.element_bz));
  fields.add_cell_scalar("B_magnitude", results.element_b);
  fields.add_cell_vector("H", as_vectors(results.element_hr, results.element_hz));
  fields.add_cell_scalar("H_magnitude", results.element_h);
  fields.add_cell_scalar("mu_r", results.element_mu_r);
  fields.add_point_vector("B_nodal", as_vectors(results.node_br, results.node_bz));
  fields.add_point_scalar("B_nodal_magnitude", results.node_b);
  for (const mesh::VtuFields::Field& f : extra.fields()) {
    using Location = mesh::VtuFields::Location;
    if (f.integer) {
      fields.add_cell_int(f.name, std::vector<int>(f.values.begin(), f.values.end()));
    } else if (f.components == 1) {
      (f.location == Location::cell ? fields.add_cell_scalar(f.name, f.values)
                                    : fields.add_point_scalar(f.name, f.values));
    } else {
      std::vector<std::array<double, 3>> v(f.values.size() / 3);
      for (std::size_t i = 0; i < v.size(); ++i)
        v[i] = {f.values[3 * i], f.values[3 * i + 1], f.values[3 * i + 2]};
      (f.location == Location::cell ? fields.add_cell_vector(f.name, v)
                                    : fields.add_point_vector(f.name, v));
    }
  }
  std::vector<std::string> names;
  for (const auto& region : solver.problem().geometry.regions) names.push_back(region.name);
  mesh::write_vtu(path, m, fields, names);
}

}  // namespace rheomag::magnetostatics
