#include "magnetostatics/line_integral.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/format_text.hpp"

namespace rheomag::magnetostatics {
namespace {

/// "x1,y1:x2,y2" -> the two points; InputError otherwise.
std::array<mesh::Point, 2> parse_line(const std::string& text) {
  std::array<double, 4> v{};
  std::istringstream in(text);
  char sep[3] = {};
  const bool ok =
      static_cast<bool>(in >> v[0] >> sep[0] >> v[1] >> sep[1] >> v[2] >> sep[2] >> v[3]) &&
      sep[0] == ',' && sep[1] == ':' && sep[2] == ',' && (in >> std::ws).eof();
  if (!ok || !std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); }))
    throw InputError("--line " + text + ": expected x1,y1:x2,y2 in metres (r,z for axisymmetric)");
  return {mesh::Point{v[0], v[1]}, mesh::Point{v[2], v[3]}};
}

/// A (nodal interpolation) at a located point.
double potential_in(const MagnetostaticSolver& solver, const Solution& solution,
                    const MeshLocation& at) {
  const mesh::Mesh& m = solver.mesh();
  double n[kMaxElementNodes], d_xi[kMaxElementNodes], d_eta[kMaxElementNodes];
  lagrange_basis(m.order, at.xi, at.eta, n, d_xi, d_eta);
  double a = 0.0;
  for (int i = 0; i < m.nodes_per_triangle(); ++i)
    a += n[i] * solution.a[m.triangles[at.element][i]];
  return a;
}

std::string model_extent(const mesh::Mesh& m) {
  double r0 = std::numeric_limits<double>::infinity(), r1 = -r0, z0 = r0, z1 = -r0;
  for (const mesh::Point& p : m.nodes) {
    r0 = std::min(r0, p.r), r1 = std::max(r1, p.r), z0 = std::min(z0, p.z), z1 = std::max(z1, p.z);
  }
  return format_text("%.6g..%.6g m by %.6g..%.6g m", r0, r1, z0, z1);
}

}  // namespace

LineField line_field(const MagnetostaticSolver& solver, const Solution& solution,
                     const std::string& line, int points) {
  if (points < 2)
    throw InputError("--points " + std::to_string(points) + ": expected at least 2 points");
  const auto ends = parse_line(line);
  LineField out;
  out.start = ends[0], out.end = ends[1];
  const double dr = out.end.r - out.start.r, dz = out.end.z - out.start.z;
  out.length = std::hypot(dr, dz);
  if (out.length <= 0.0) throw InputError("--line " + line + ": the two ends are the same point");
  const double tr = dr / out.length, tz = dz / out.length;  // tangent; normal (-tz, tr)
  const mesh::Mesh& m = solver.mesh();
  const bool axisymmetric = solver.problem().symmetry == cases::Symmetry::axisymmetric;
  std::array<double, 2> end_a{};
  for (int k = 0; k < points; ++k) {
    const double t = static_cast<double>(k) / (points - 1);
    const mesh::Point p{out.start.r + t * dr, out.start.z + t * dz};
    const std::optional<MeshLocation> at = locate_in_mesh(m, p);
    if (!at) {
      throw InputError(format_text("--line %s: the point (%.6g, %.6g) m is outside the model; "
                                   "the model spans ",
                                   line.c_str(), p.r, p.z) +
                       model_extent(m) + " (holes excluded)");
    }
    const auto b = flux_density_in(solver, solution, *at);
    const auto h = solver.assembler().law(at->element).h(b[0], b[1]);
    LineSample sample;
    sample.s = t * out.length, sample.r = p.r, sample.z = p.z;
    sample.b_t = b[0] * tr + b[1] * tz;
    sample.b_n = -b[0] * tz + b[1] * tr;
    sample.b = std::hypot(b[0], b[1]);
    sample.h_t = h[0] * tr + h[1] * tz;
    sample.h_n = -h[0] * tz + h[1] * tr;
    sample.h = std::hypot(h[0], h[1]);
    out.samples.push_back(sample);
    if (k == 0 || k == points - 1) end_a[k == 0 ? 0 : 1] = potential_in(solver, solution, *at);
  }
  out.normal_flux = axisymmetric ? kTwoPi * (out.end.r * end_a[1] - out.start.r * end_a[0])
                                 : solver.problem().depth * (end_a[0] - end_a[1]);
  return out;
}

nlohmann::json lines_json(const std::vector<LineField>& lines) {
  nlohmann::json out = nlohmann::json::array();
  for (const LineField& line : lines) {
    nlohmann::json samples = nlohmann::json::array();
    for (const LineSample& s : line.samples) {
      samples.push_back({{"s", s.s},
                         {"r", s.r},
                         {"z", s.z},
                         {"b_n", s.b_n},
                         {"b_t", s.b_t},
                         {"b", s.b},
                         {"h_n", s.h_n},
                         {"h_t", s.h_t},
                         {"h", s.h}});
    }
    out.push_back({{"start", {line.start.r, line.start.z}},
                   {"end", {line.end.r, line.end.z}},
                   {"length", line.length},
                   {"normal_flux", line.normal_flux},
                   {"samples", samples}});
  }
  return out;
}

std::string lines_text(const std::vector<LineField>& lines, cases::Symmetry symmetry) {
  const bool planar = symmetry == cases::Symmetry::planar;
  std::string out;
  for (const LineField& line : lines) {
    out += format_text(
        "\nline (%.6g, %.6g) to (%.6g, %.6g) m, length %.6g m: flux through it %.6g Wb "
        "(normal: the direction turned 90 degrees counter-clockwise)\n",
        line.start.r, line.start.z, line.end.r, line.end.z, line.length, line.normal_flux);
    out += format_text("%12s %12s %12s %12s %12s %12s %12s %12s\n", "s [m]",
                       planar ? "x [m]" : "r [m]", planar ? "y [m]" : "z [m]", "B_n [T]", "B_t [T]",
                       "|B| [T]", "H_n [A/m]", "H_t [A/m]");
    for (const LineSample& s : line.samples) {
      out += format_text("%12.6g %12.6g %12.6g %12.6g %12.6g %12.6g %12.6g %12.6g\n", s.s, s.r, s.z,
                         s.b_n, s.b_t, s.b, s.h_n, s.h_t);
    }
  }
  return out;
}

}  // namespace rheomag::magnetostatics
