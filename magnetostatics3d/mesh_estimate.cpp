#include "magnetostatics3d/mesh_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "core/memory_limit.hpp"

namespace rheomag::magnetostatics3d {
namespace {

/// Area and volume of revolution (per radian) of each region of a linear meridian mesh.
struct RegionMeasure {
  std::vector<double> area;           // [m^2]
  std::vector<double> radial_moment;  // integral of r dA [m^3]
};

RegionMeasure region_measures(const mesh::Mesh& meridian, std::size_t regions) {
  RegionMeasure m{std::vector<double>(regions, 0.0), std::vector<double>(regions, 0.0)};
  for (std::size_t t = 0; t < meridian.triangles.size(); ++t) {
    const auto& tri = meridian.triangles[t];
    const mesh::Point& a = meridian.nodes[tri[0]];
    const mesh::Point& b = meridian.nodes[tri[1]];
    const mesh::Point& c = meridian.nodes[tri[2]];
    const double area = 0.5 * std::abs((b.r - a.r) * (c.z - a.z) - (c.r - a.r) * (b.z - a.z));
    const std::size_t r = static_cast<std::size_t>(meridian.region[t]);
    if (r >= regions) continue;
    m.area[r] += area;
    m.radial_moment[r] += area * std::abs(a.r + b.r + c.r) / 3.0;
  }
  return m;
}

double size_of(const std::vector<double>& sizes, std::size_t r, double default_size) {
  return r < sizes.size() && sizes[r] > 0 ? sizes[r] : default_size;
}

/// Measured on the bundled valves (docs/magnetostatics3d.md): TetGen's elements per regular
/// tetrahedron of the volume limit, and the 2D mesher's triangles per equilateral triangle of the
/// size (check_mesh_size uses the same 2).
constexpr double kTetgenElementsPerLimit = 4.0;
constexpr double kTrianglesPerEquilateral = 2.0;

/// Peak bytes per tetrahedron of the solve: the mesh, edges, the sparse system and, growing
/// with the size, the fill of the Cholesky factor (nested dissection in 3D: n^(4/3)).
/// Peak RSS of `solve --3d --full --mesher swept` on small_valve with a hole in air: 1.78 GB for
/// 336,804 tetrahedra (5270 B each), 3.55 GB for 609,246 (5830 B each).
constexpr double kBytesPerTetrahedron = 2700.0;
constexpr double kFillBytesPerTetrahedron = 37.0;
/// AMS (no factor): peak RSS of `solve --3d --linear-solver ams` 0.576 GB for the lead-slot half
/// model's 351k tetrahedra (1640 B each) and 0.24 GB for the annular valve's TetGen wedge (139k,
/// 1730 B each); 1800 B each, rounded up.
constexpr double kAmsBytesPerTetrahedron = 1800.0;

std::string count_text(double count) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", count);
  return text;
}

}  // namespace

double MeshEstimate3d::tetrahedra() const {
  double total = 0.0;
  for (double n : region_tetrahedra) total += n;
  return total;
}

double solve_memory_bytes(double tetrahedra, LinearSolver3d linear) {
  if (linear == LinearSolver3d::ams) return tetrahedra * kAmsBytesPerTetrahedron;
  return tetrahedra * (kBytesPerTetrahedron + kFillBytesPerTetrahedron * std::cbrt(tetrahedra));
}

MeshEstimate3d estimate_tetgen_mesh(const mesh::Mesh& meridian, const std::vector<double>& sizes,
                                    double default_size, double span) {
  const std::size_t regions = sizes.size();
  const RegionMeasure m = region_measures(meridian, regions);
  MeshEstimate3d e;
  e.region_tetrahedra.assign(regions, 0.0);
  for (std::size_t r = 0; r < regions; ++r) {
    const double h = size_of(sizes, r, default_size);
    if (!(h > 0)) continue;
    const double regular = h * h * h / (6.0 * std::sqrt(2.0));
    e.region_tetrahedra[r] = kTetgenElementsPerLimit * span * m.radial_moment[r] / regular;
  }
  return e;
}

MeshEstimate3d estimate_swept_mesh(const mesh::Mesh& meridian, const std::vector<double>& sizes,
                                   double default_size, std::size_t angular_steps) {
  const std::size_t regions = sizes.size();
  const RegionMeasure m = region_measures(meridian, regions);
  MeshEstimate3d e;
  e.region_tetrahedra.assign(regions, 0.0);
  for (std::size_t r = 0; r < regions; ++r) {
    const double h = size_of(sizes, r, default_size);
    if (!(h > 0)) continue;
    const double triangles = kTrianglesPerEquilateral * m.area[r] / (std::sqrt(3.0) / 4.0 * h * h);
    e.region_tetrahedra[r] = 3.0 * triangles * static_cast<double>(angular_steps);
  }
  return e;
}

MeshEstimate3d count_swept_mesh(const mesh::Mesh& sized_meridian, std::size_t regions,
                                std::size_t angular_steps) {
  MeshEstimate3d e;
  e.region_tetrahedra.assign(regions, 0.0);
  for (int r : sized_meridian.region)
    if (r >= 0 && static_cast<std::size_t>(r) < regions)
      e.region_tetrahedra[static_cast<std::size_t>(r)] += 3.0 * static_cast<double>(angular_steps);
  return e;
}

void require_mesh_within_memory(const MeshEstimate3d& estimate, double max_memory,
                                const cases::Problem& closed, const std::vector<double>& sizes,
                                const std::vector<std::string>& size_reasons) {
  const double tetrahedra = estimate.tetrahedra();
  const double bytes = solve_memory_bytes(tetrahedra, estimate.linear);
  if (!(max_memory > 0) || bytes / estimate.spread <= max_memory) return;
  const auto& counts = estimate.region_tetrahedra;
  const std::size_t largest =
      static_cast<std::size_t>(std::max_element(counts.begin(), counts.end()) - counts.begin());
  char size[32];
  std::snprintf(size, sizeof size, "%.3g m", largest < sizes.size() ? sizes[largest] : 0.0);
  std::string driver = "region '" + closed.geometry.regions[largest].name + "' (" +
                       count_text(counts[largest]) + " tetrahedra";
  if (largest < sizes.size() && sizes[largest] > 0) driver += std::string(" of ") + size;
  if (largest < size_reasons.size() && !size_reasons[largest].empty())
    driver += ": " + size_reasons[largest];
  driver += ")";
  throw InputError(
      closed.geometry.source + ": the 3D mesh (" + estimate.mesher + ") would have about " +
      count_text(tetrahedra) + " tetrahedra and its solve (--linear-solver " +
      std::string(kLinearSolver3dNames.name(estimate.linear)) + ") would need about " +
      memory_size_text(bytes) + ", more than the " + memory_size_text(max_memory) +
      " allowed (--max-memory; default 3/4 of the memory available: physical, ulimit "
      "-v, cgroup); most of them in " +
      driver + "; expected coarser elements there or a larger --max-memory" +
      (estimate.linear == LinearSolver3d::cholmod
           ? " (or --linear-solver ams, no factor: about " +
                 memory_size_text(solve_memory_bytes(tetrahedra, LinearSolver3d::ams)) + ")"
           : std::string()));
}

}  // namespace rheomag::magnetostatics3d
