// FEMM 4.2 .fem writer. Format facts from the FEMM 4.2 manual and the files FEMM writes; the
// reader (femm_import.cpp) reads back everything written here.

#include "case/femm_export.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>
#include <numeric>
#include <sstream>
#include <utility>
#include <vector>

#include "case/femm_import.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"
#include "mesh/mesher.hpp"
#include "mesh/triangle.hpp"

namespace rheomag::cases {

double edge_to_femm_mesh_size(double edge) {
  return edge / femm_mesh_size_to_edge(1.0);
}

namespace {

/// Shortest text that reads back as the same double.
std::string num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

/// `text` as a quoted .fem string. FEMM reads a name up to the end of its line and to the next
/// double quote, so a name holding either cannot be written: InputError naming `what` (e.g.
/// "material name") and the source, never a file that does not read back.
std::string femm_quoted(const std::string& text, const std::string& what,
                        const std::string& source) {
  for (const char ch : text) {
    if (ch == '"' || (static_cast<unsigned char>(ch) < 0x20 && ch != '\t')) {
      std::string shown;
      for (const char c : text)
        shown += c == '\n'   ? std::string("\\n")
                 : c == '\r' ? std::string("\\r")
                             : std::string(1, c);
      throw InputError(source + ": " + what + " '" + shown +
                       "' cannot be written to a .fem: FEMM's names are one line without "
                       "double quotes; expected a name without a line break, control character "
                       "or '\"' (rename it in the case)");
    }
  }
  return "\"" + text + "\"";
}

/// `text` made safe for a .fem comment: line breaks, control characters and double quotes
/// become spaces or single quotes.
std::string femm_comment_text(std::string text) {
  for (char& ch : text) {
    if (ch == '"')
      ch = '\'';
    else if (static_cast<unsigned char>(ch) < 0x20)
      ch = ' ';
  }
  return text;
}

/// One block label of the written file.
struct Label {
  mesh::Point at;
  int region = -1;    // index into problem.regions
  double edge = 0.0;  // target edge length [m], 0 = FEMM's automatic size
};

/// Union-find root.
int root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

/// True when the mesh edge p-q lies on a PSLG segment.
bool on_segment(const mesh::Pslg& g, mesh::Point p, mesh::Point q, double tolerance) {
  for (const mesh::Segment& s : g.segments) {
    const mesh::Point a = g.points[s.a], b = g.points[s.b];
    const double length = std::hypot(b.r - a.r, b.z - a.z);
    if (length == 0.0) continue;
    auto distance = [&](mesh::Point x) {
      return std::abs((b.r - a.r) * (x.z - a.z) - (b.z - a.z) * (x.r - a.r)) / length;
    };
    auto inside = [&](mesh::Point x) {
      const double t = ((x.r - a.r) * (b.r - a.r) + (x.z - a.z) * (b.z - a.z)) / (length * length);
      return t >= -1e-9 && t <= 1.0 + 1e-9;
    };
    if (distance(p) <= tolerance && distance(q) <= tolerance && inside(p) && inside(q)) return true;
  }
  return false;
}

/// A label for each seed, plus one per further connected area of the default region, with the
/// mean edge length of each region in `m` as the size of regions without a mesh size; the index
/// into the returned labels of every triangle of `m` goes to `triangle_label`.
std::vector<Label> block_labels(const Problem& problem, const mesh::Mesh& m,
                                std::vector<int>& triangle_label) {
  const mesh::Pslg& g = problem.geometry;
  const int regions = static_cast<int>(g.regions.size());
  std::vector<double> edge_sum(regions, 0.0);
  std::vector<int> edge_count(regions, 0);
  const int triangles = static_cast<int>(m.triangles.size());
  double extent = 0.0;
  for (const mesh::Point& p : m.nodes) extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
  std::map<std::pair<int, int>, int> first_triangle;  // default-region edges
  std::vector<int> parent(triangles);
  std::iota(parent.begin(), parent.end(), 0);
  for (int e = 0; e < triangles; ++e) {
    const auto& t = m.triangles[e];
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      edge_sum[m.region[e]] += std::hypot(m.nodes[a].r - m.nodes[b].r, m.nodes[a].z - m.nodes[b].z);
      ++edge_count[m.region[e]];
      if (m.region[e] != g.default_region) continue;
      const auto key = std::minmax(a, b);
      auto [it, inserted] = first_triangle.emplace(key, e);
      if (!inserted && !on_segment(g, m.nodes[a], m.nodes[b], 1e-9 * extent))
        parent[root(parent, e)] = root(parent, it->second);
    }
  }
  std::vector<Label> labels;
  auto size_of = [&](int region) {
    if (g.regions[region].mesh_size > 0.0) return g.regions[region].mesh_size;
    return edge_count[region] > 0 ? edge_sum[region] / edge_count[region] : 0.0;
  };
  std::vector<int> label_of_region(regions, -1);
  for (int r = 0; r < regions; ++r) {
    if (r == g.default_region) continue;
    label_of_region[r] = static_cast<int>(labels.size());
    labels.push_back({g.regions[r].seed, r, size_of(r)});
  }
  triangle_label.assign(triangles, -1);
  for (int e = 0; e < triangles; ++e) triangle_label[e] = label_of_region[m.region[e]];
  if (g.default_region < 0) return labels;
  // One label per connected area of the default region, at the centroid of its largest
  // triangle (strictly inside the area).
  std::map<int, std::pair<double, int>> largest;  // component root -> (area, triangle)
  for (int e = 0; e < triangles; ++e) {
    if (m.region[e] != g.default_region) continue;
    const auto& t = m.triangles[e];
    const mesh::Point a = m.nodes[t[0]], b = m.nodes[t[1]], c = m.nodes[t[2]];
    const double area = mesh::triangle_area(a, b, c);
    auto& best = largest[root(parent, e)];
    if (area > best.first) best = {area, e};
  }
  std::map<int, int> label_of_component;
  for (const auto& [component, best] : largest) {
    const auto& t = m.triangles[best.second];
    const mesh::Point centroid =
        mesh::triangle_centroid(m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]]);
    label_of_component[component] = static_cast<int>(labels.size());
    labels.push_back({centroid, g.default_region, size_of(g.default_region)});
  }
  for (int e = 0; e < triangles; ++e)
    if (m.region[e] == g.default_region) triangle_label[e] = label_of_component[root(parent, e)];
  return labels;
}

}  // namespace

std::string write_femm(const Problem& problem, const mesh::MeshOptions& mesh_options) {
  if (problem.outer != OuterBoundary::none)
    throw InputError(problem.geometry.source +
                     ": the outer boundary must be closed before a .fem is written");
  mesh::MeshOptions options = mesh_options;
  options.order = 1;
  options.min_gap_elements = problem.min_gap_elements;
  return write_femm_for_mesh(problem, mesh::generate_mesh(problem.geometry, options)).text;
}

FemmModel write_femm_for_mesh(const Problem& problem, const mesh::Mesh& m) {
  const mesh::Pslg& g = problem.geometry;
  if (problem.outer != OuterBoundary::none)
    throw InputError(g.source + ": the outer boundary must be closed before a .fem is written");
  if (problem.regions.size() != g.regions.size())
    throw InputError(g.source + ": region data and region seeds differ in number");
  const bool axisymmetric = problem.symmetry == Symmetry::axisymmetric;

  // Blocks: one per (material, fixed current density) pair used by a meshed region.
  std::vector<std::pair<int, double>> blocks;
  std::vector<int> block_of_region(problem.regions.size(), 0);  // 0 = <No Mesh> (hole)
  for (std::size_t r = 0; r < problem.regions.size(); ++r) {
    if (g.regions[r].hole) continue;
    const RegionData& d = problem.regions[r];
    if (d.material < 0 || d.material >= static_cast<int>(problem.materials.size()))
      throw InputError(g.source + ": region '" + g.regions[r].name + "' has no material");
    const std::pair<int, double> key{d.material, d.current_density};
    auto it = std::find(blocks.begin(), blocks.end(), key);
    if (it == blocks.end()) it = blocks.insert(blocks.end(), key);
    block_of_region[r] = static_cast<int>(it - blocks.begin()) + 1;
    if (d.circuit >= 0 && d.turns != std::round(d.turns))
      throw InputError(g.source + ": region '" + g.regions[r].name + "' has " + num(d.turns) +
                       " turns; a .fem holds whole turns only");
  }

  // rheomag writes arcs as chords, so an (anti)periodic edge would become several FEMM segments,
  // which FEMM refuses (it pairs exactly two segments or two arcs).
  for (const BoundaryCondition& b : problem.boundaries)
    if (b.kind == BoundaryKind::periodic || b.kind == BoundaryKind::antiperiodic)
      throw InputError(g.source + ": boundary '" + b.name +
                       "' is (anti)periodic; export writes edges as straight pieces, which "
                       "FEMM cannot pair, so (anti)periodic models are not exported");
  std::vector<int> triangle_label;
  const std::vector<Label> labels = block_labels(problem, m, triangle_label);

  // Length unit of the file: metres, or the unit of the magnet direction expressions (FEMM
  // evaluates them in the file's unit), which must then be one FEMM knows and the same for all.
  const std::pair<double, const char*> units[] = {{1.0, "meters"},       {1e-2, "centimeters"},
                                                  {1e-3, "millimeters"}, {1e-6, "micrometers"},
                                                  {0.0254, "inches"},    {2.54e-5, "mils"}};
  std::pair<double, const char*> unit = units[0];
  bool unit_set = false;
  for (std::size_t r = 0; r < problem.regions.size(); ++r) {
    const MagnetDirection& m = problem.regions[r].magnetisation;
    if (m.expression.empty() || problem.materials[problem.regions[r].material].coercivity == 0.0)
      continue;
    const auto* known = std::find_if(std::begin(units), std::end(units), [&](const auto& u) {
      return std::abs(u.first - m.length_unit) <= 1e-12 * u.first;
    });
    if (known == std::end(units) || (unit_set && known->first != unit.first))
      throw InputError(g.source + ": region '" + g.regions[r].name +
                       "': magnet direction expressions in different or unknown length units "
                       "cannot share one .fem");
    unit = *known;
    unit_set = true;
  }
  const double u = unit.first;

  std::ostringstream out;
  out << "[Format]      =  4.0\n[Frequency]   =  0\n[Precision]   =  1e-08\n"
      << "[MinAngle]    =  30\n[Depth]       =  " << num(axisymmetric ? 1.0 : problem.depth / u)
      << "\n[LengthUnits] =  " << unit.second
      << "\n[ProblemType] =  " << (axisymmetric ? "axisymmetric" : "planar")
      << "\n[Coordinates] =  cartesian\n"
      << "[ACSolver]    =  0\n[Comment]     =  \"written by rheomag export from "
      << femm_comment_text(g.source) << "\"\n";

  out << "[PointProps]  = " << problem.point_conditions.size() << "\n";
  for (const PointCondition& p : problem.point_conditions) {
    out << "  <BeginPoint>\n    <PointName> = "
        << femm_quoted(p.name, "point property name", g.source)
        << "\n    <I_re> = " << num(p.prescribed ? 0.0 : p.current)
        << "\n    <I_im> = 0\n    <A_re> = " << num(p.prescribed ? p.a_value : 0.0)
        << "\n    <A_im> = 0\n  <EndPoint>\n";
  }
  out << "[BdryProps]   = " << problem.boundaries.size() << "\n";
  for (const BoundaryCondition& b : problem.boundaries) {
    const bool mixed = b.kind == BoundaryKind::mixed;
    // FEMM's mixed condition: (1/mu) dA/dn + c0 A + c1 = 0; rheomag's: nu dA/dn + c0 A = c1.
    out << "  <BeginBdry>\n    <BdryName> = " << femm_quoted(b.name, "boundary name", g.source)
        << "\n    <BdryType> = " << (mixed ? 2 : 0)
        << "\n    <A_0> = " << num(mixed ? 0.0 : b.a_value)
        << "\n    <A_1> = " << num(mixed ? 0.0 : b.a_per_r * u)
        << "\n    <A_2> = " << num(mixed ? 0.0 : b.a_per_z * u)
        << "\n    <Phi> = 0\n    <c0> = " << num(mixed ? b.c0 : 0.0)
        << "\n    <c0i> = 0\n    <c1> = " << num(mixed ? 0.0 - b.c1 : 0.0)
        << "\n    <c1i> = 0\n    <Mu_ssd> = 0\n    <Sigma_ssd> = 0\n  <EndBdry>\n";
  }
  out << "[BlockProps]  = " << blocks.size() << "\n";
  std::map<std::string, int> name_use;
  for (const auto& [material, density] : blocks) name_use[problem.materials[material].name]++;
  std::map<std::string, int> name_seen;
  for (const auto& [material, density] : blocks) {
    const Material& m = problem.materials[material];
    // An anisotropic material as FEMM's LamType 0 at fill 1: mu along x and y as they are.
    const std::array<double, 2> mu = m.mu_r_axes.value_or(std::array{m.mu_r, m.mu_r});
    std::string name = m.name;
    if (name_use[name] > 1) name += "_" + std::to_string(++name_seen[name]);
    out << "  <BeginBlock>\n    <BlockName> = " << femm_quoted(name, "material name", g.source)
        << "\n    <Mu_x> = " << num(mu[0]) << "\n    <Mu_y> = " << num(mu[1])
        << "\n    <H_c> = " << num(m.coercivity) << "\n    <J_re> = " << num(density * 1e-6)
        << "\n    <J_im> = 0\n    <Sigma> = " << num(m.conductivity.value_or(0.0) * 1e-6)
        << "\n    <d_lam> = 0\n    <Phi_h> = 0\n    <Phi_hx> = 0\n    <Phi_hy> = 0\n"
        << "    <LamType> = 0\n    <LamFill> = 1\n    <NStrands> = 0\n    <WireD> = 0\n"
        << "    <BHPoints> = " << m.bh.size() << "\n";
    for (const BhPoint& p : m.bh) out << "      " << num(p.b) << "\t" << num(p.h) << "\n";
    out << "  <EndBlock>\n";
  }
  out << "[CircuitProps]  = " << problem.circuits.size() << "\n";
  for (const Circuit& c : problem.circuits) {
    out << "  <BeginCircuit>\n    <CircuitName> = " << femm_quoted(c.name, "circuit name", g.source)
        << "\n    <TotalAmps_re> = " << num(c.current)
        << "\n    <TotalAmps_im> = 0\n    <CircuitType> = " << (c.parallel ? 0 : 1)
        << "\n  <EndCircuit>\n";
  }

  // Point properties are numbered in problem order; a point carries at most one.
  std::vector<int> point_prop(g.points.size(), 0);
  for (std::size_t k = 0; k < problem.point_conditions.size(); ++k)
    point_prop.at(problem.point_conditions[k].point) = static_cast<int>(k) + 1;
  out << "[NumPoints] = " << g.points.size() << "\n";
  for (std::size_t i = 0; i < g.points.size(); ++i)
    out << num(g.points[i].r / u) << "\t" << num(g.points[i].z / u) << "\t" << point_prop[i]
        << "\t0\n";
  out << "[NumSegments] = " << g.segments.size() << "\n";
  for (const mesh::Segment& s : g.segments) {
    out << s.a << "\t" << s.b << "\t" << (s.max_length > 0.0 ? num(s.max_length / u) : "-1") << "\t"
        << s.boundary + 1 << "\t0\t0\n";
  }
  out << "[NumArcSegments] = 0\n";
  std::vector<const mesh::RegionSeed*> holes;
  for (const mesh::RegionSeed& seed : g.regions)
    if (seed.hole) holes.push_back(&seed);
  out << "[NumHoles] = " << holes.size() << "\n";
  for (const mesh::RegionSeed* h : holes)
    out << num(h->seed.r / u) << "\t" << num(h->seed.z / u) << "\t0\n";
  std::vector<const Label*> meshed;
  std::vector<int> written_index(labels.size(), -1);
  for (std::size_t k = 0; k < labels.size(); ++k) {
    if (g.regions[labels[k].region].hole) continue;
    written_index[k] = static_cast<int>(meshed.size());
    meshed.push_back(&labels[k]);
  }
  FemmModel model;
  model.length_unit = u;
  model.label_region.reserve(meshed.size());
  for (const Label* l : meshed) model.label_region.push_back(l->region);
  model.triangle_label.reserve(triangle_label.size());
  for (int k : triangle_label) model.triangle_label.push_back(k < 0 ? -1 : written_index[k]);
  out << "[NumBlockLabels] = " << meshed.size() << "\n";
  for (const Label* l : meshed) {
    const RegionData& d = problem.regions[l->region];
    const MagnetDirection& m = d.magnetisation;
    out << num(l->at.r / u) << "\t" << num(l->at.z / u) << "\t" << block_of_region[l->region]
        << "\t" << (l->edge > 0.0 ? num(edge_to_femm_mesh_size(l->edge) / u) : "-1") << "\t"
        << (d.circuit >= 0 ? d.circuit + 1 : 0) << "\t"
        << num(m.expression.empty() ? m.degrees : 0.0) << "\t0\t"
        << (d.circuit >= 0 ? static_cast<long>(std::round(d.turns)) : 1) << "\t0";
    if (!m.expression.empty())
      out << "\t" << femm_quoted(m.expression, "magnet direction expression", g.source);
    out << "\n";
  }
  model.text = out.str();
  return model;
}

}  // namespace rheomag::cases
