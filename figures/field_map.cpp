#include "figures/field_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "plot/colour_bar.hpp"
#include "plot/triangle_field.hpp"

namespace rheomag::figures {

namespace {

namespace ms = magnetostatics;

/// True for a region drawn by the zoom: not plain air (a linear mu_r = 1 region without
/// current, magnetisation or gap).
bool is_device_region(const cases::Problem& problem, int region) {
  const mesh::RegionSeed& seed = problem.geometry.regions[region];
  if (seed.hole) return false;
  if (seed.gap != mesh::GapKind::none) return true;
  const cases::RegionData& data = problem.regions[region];
  if (data.circuit >= 0 || data.current_density != 0.0) return true;
  if (data.material < 0) return false;
  const cases::Material& material = problem.materials[data.material];
  return !material.bh.empty() || material.mu_r != 1.0 || material.mu_r_axes ||
         material.coercivity != 0.0;
}

/// The bounding box (mm) of the device regions' triangles, or of the whole mesh without any.
std::pair<plot::Range, plot::Range> device_box(const ms::MagnetostaticSolver& solver) {
  const mesh::Mesh& m = solver.mesh();
  const cases::Problem& problem = solver.problem();
  const double inf = std::numeric_limits<double>::infinity();
  plot::Range x{inf, -inf}, y{inf, -inf};
  for (int pass = 0; pass < 2 && !(x.high > x.low); ++pass) {
    for (std::size_t e = 0; e < m.triangles.size(); ++e) {
      if (pass == 0 && !is_device_region(problem, m.region[e])) continue;
      for (int i = 0; i < 3; ++i) {
        const mesh::Point& p = m.nodes[m.triangles[e][i]];
        x.low = std::min(x.low, 1e3 * p.r), x.high = std::max(x.high, 1e3 * p.r);
        y.low = std::min(y.low, 1e3 * p.z), y.high = std::max(y.high, 1e3 * p.z);
      }
    }
  }
  return {x, y};
}

/// The pieces drawn for one mesh: flat sub-triangles over the mesh nodes (mm), with |B| at
/// each piece's centre and the flux function at the nodes.
struct Pieces {
  plot::TriangleMesh mesh;
  std::vector<double> b;    ///< per sub-triangle [T]
  std::vector<double> psi;  ///< per node: r A_phi [Wb/rad] or A_z [Wb/m]
};

/// Splits the triangles whose box meets the view into pieces (P2: four, by the edge midpoints).
Pieces pieces_in_view(const ms::MagnetostaticSolver& solver, const ms::Solution& solution,
                      const plot::Axes& axes) {
  const mesh::Mesh& m = solver.mesh();
  const bool axisymmetric = solver.problem().symmetry == cases::Symmetry::axisymmetric;
  Pieces pieces;
  pieces.mesh.points.reserve(m.nodes.size());
  pieces.psi.reserve(m.nodes.size());
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    const mesh::Point& p = m.nodes[i];
    pieces.mesh.points.push_back({1e3 * p.r, 1e3 * p.z});
    pieces.psi.push_back(axisymmetric ? p.r * solution.a[i] : solution.a[i]);
  }
  // Sub-triangles of a P2 triangle (local node indices) and their centres (xi, eta).
  static constexpr int kSplit[4][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};
  static constexpr double kCentre[4][2] = {
      {1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6}, {1.0 / 6, 2.0 / 3}, {1.0 / 3, 1.0 / 3}};
  const plot::Range vx = axes.x(), vy = axes.y();
  for (int e = 0; e < static_cast<int>(m.triangles.size()); ++e) {
    const auto& t = m.triangles[e];
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    for (int i = 0; i < 3; ++i) {
      const auto& p = pieces.mesh.points[t[i]];
      x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), y0 = std::min(y0, p[1]),
      y1 = std::max(y1, p[1]);
    }
    if (x1 < vx.low || x0 > vx.high || y1 < vy.low || y0 > vy.high) continue;
    if (m.order == 1) {
      pieces.mesh.triangles.push_back({t[0], t[1], t[2]});
      const auto b = ms::flux_density_in(solver, solution, {e, 1.0 / 3, 1.0 / 3});
      pieces.b.push_back(std::hypot(b[0], b[1]));
      continue;
    }
    for (int k = 0; k < 4; ++k) {
      pieces.mesh.triangles.push_back({t[kSplit[k][0]], t[kSplit[k][1]], t[kSplit[k][2]]});
      const auto b = ms::flux_density_in(solver, solution, {e, kCentre[k][0], kCentre[k][1]});
      pieces.b.push_back(std::hypot(b[0], b[1]));
    }
  }
  return pieces;
}

/// The colour map of |B|: from 0 to a round value above the 99th percentile of the pieces
/// (pole corners, where |B| is singular, would otherwise set the scale); higher values take
/// the top colour.
plot::ColourMap b_colours(std::vector<double> b, int bins) {
  double top = 0.0;
  if (!b.empty()) {
    const std::size_t k = static_cast<std::size_t>(0.99 * static_cast<double>(b.size() - 1));
    std::nth_element(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(k), b.end());
    top = b[k];
  }
  if (!(top > 0.0) || !std::isfinite(top)) return plot::ColourMap(0.0, 1.0, bins);
  const std::vector<double> ticks = plot::nice_ticks(0.0, top, 5);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : top;
  return plot::ColourMap(0.0, std::ceil(top / step - 1e-9) * step, bins);
}

/// Edges (vertex pairs) where the region changes or the mesh ends.
std::vector<plot::ContourSegment> region_outlines(const mesh::Mesh& m) {
  std::map<std::pair<int, int>, std::pair<int, int>> edges;  // -> (region, count)
  std::vector<plot::ContourSegment> outlines;
  for (std::size_t e = 0; e < m.triangles.size(); ++e) {
    for (int i = 0; i < 3; ++i) {
      int a = m.triangles[e][i], b = m.triangles[e][(i + 1) % 3];
      if (a > b) std::swap(a, b);
      auto [it, inserted] = edges.try_emplace({a, b}, m.region[e], 1);
      if (!inserted) {
        ++it->second.second;
        if (it->second.first == m.region[e]) it->second.first = -2;  // interior: not drawn
      }
    }
  }
  for (const auto& [edge, state] : edges) {
    if (state.first == -2) continue;
    const mesh::Point& a = m.nodes[edge.first];
    const mesh::Point& b = m.nodes[edge.second];
    outlines.push_back({{1e3 * a.r, 1e3 * a.z}, {1e3 * b.r, 1e3 * b.z}, 0});
  }
  return outlines;
}

/// Each gap's name beside it (right of an annular gap, above a radial one), with a leader.
void label_gaps(cairo_t* cr, const plot::Axes& axes, const ms::Results& results) {
  for (const ms::GapResult& g : results.gaps) {
    if (g.line_samples == 0) continue;
    const bool annular = g.kind == mesh::GapKind::annular;
    const auto centre = axes.to_px(0.5e3 * (g.line_start.r + g.line_end.r),
                                   0.5e3 * (g.line_start.z + g.line_end.z));
    const double lx = centre[0] + (annular ? 28.0 : 16.0), ly = centre[1] - (annular ? 0.0 : 24.0);
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_set_line_width(cr, 1.0);
    cairo_move_to(cr, centre[0], centre[1]);
    cairo_line_to(cr, lx - 2.0, ly);
    cairo_stroke(cr);
    plot::draw_text(cr, g.name, lx, ly, 12.0, 0.0, 0.5, true);
  }
}

}  // namespace

FieldMap draw_field_map(const ms::MagnetostaticSolver& solver, const ms::Solution& solution,
                        const ms::Results& results, const FieldMapOptions& options) {
  const bool axisymmetric = solver.problem().symmetry == cases::Symmetry::axisymmetric;
  auto [x, y] = device_box(solver);
  const double pad = options.margin * std::max(x.high - x.low, y.high - y.low);
  x = {x.low - pad, x.high + pad}, y = {y.low - pad, y.high + pad};
  if (axisymmetric) x.low = std::max(x.low, 0.0);  // nothing left of the axis
  const double w = options.width, h = options.height;
  const plot::Rect frame{70.0, options.title.empty() ? 20.0 : 40.0, w - 70.0 - 110.0,
                         h - (options.title.empty() ? 20.0 : 40.0) - 55.0};
  plot::Axes axes = plot::Axes::equal_aspect(frame, x, y);
  if (axisymmetric && axes.x().low < 0.0)  // widened past the axis: show r >= 0 only
    axes = plot::Axes(frame, {0.0, axes.x().high - axes.x().low}, axes.y());
  const Pieces pieces = pieces_in_view(solver, solution, axes);
  plot::ColourMap colours = b_colours(pieces.b, options.bins);

  plot::Figure figure(options.width, options.height);
  cairo_t* cr = figure.cr();
  cairo_save(cr);
  axes.clip(cr);
  plot::fill_triangles(cr, axes, pieces.mesh, pieces.b, colours);
  if (options.flux_lines > 0) {
    const auto [low, high] = std::minmax_element(pieces.psi.begin(), pieces.psi.end());
    if (*high > *low) {
      const auto levels = plot::centred_levels(*low, *high, options.flux_lines);
      plot::draw_segments(cr, axes, plot::contour_segments(pieces.mesh, pieces.psi, levels),
                          {0.0, 0.0, 0.0}, 0.9);
    }
  }
  plot::draw_segments(cr, axes, region_outlines(solver.mesh()), {0.85, 0.85, 0.85}, 0.8);
  if (options.gap_labels) label_gaps(cr, axes, results);
  cairo_restore(cr);
  axes.draw(cr, axisymmetric ? "r [mm]" : "x [mm]", axisymmetric ? "z [mm]" : "y [mm]");
  if (!options.title.empty()) plot::draw_text(cr, options.title, 0.5 * w, 12.0, 14.0, 0.5, 0.0);
  plot::draw_colour_bar(cr, {w - 85.0, frame.y + 20.0, 22.0, frame.height - 20.0}, colours,
                        "|B| [T]");
  return {std::move(figure), axes, colours};
}

}  // namespace rheomag::figures
