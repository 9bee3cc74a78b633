#include "magnetostatics3d/solve3d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <numbers>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/memory_limit.hpp"
#include "magnetostatics/domain.hpp"
#include "magnetostatics3d/coil_source.hpp"
#include "magnetostatics3d/features.hpp"
#include "magnetostatics3d/mesh_estimate.hpp"
#include "magnetostatics3d/plc.hpp"
#include "magnetostatics3d/region_box.hpp"
#include "magnetostatics3d/revolve.hpp"
#include "magnetostatics3d/swept_mesh.hpp"
#include "magnetostatics3d/warm_start.hpp"
#include "mesh/mesher.hpp"

namespace rheomag::magnetostatics3d {
namespace {

/// Volume of a regular tetrahedron of edge h.
double tet_volume(double h) {
  return h * h * h / (6.0 * std::sqrt(2.0));
}

/// Target element edge length per region [m] (0: none, the background).
std::vector<double> region_sizes(const cases::Problem& closed, const std::vector<RegionBox>& box,
                                 const Solve3dOptions& options) {
  // Gaps first: thickness / layers; other regions no finer than the finest gap.
  std::vector<double> h(closed.regions.size(), 0.0);
  double finest_gap = INFINITY;
  for (std::size_t r = 0; r < closed.regions.size(); ++r) {
    const mesh::GapKind gap = closed.geometry.regions[r].gap;
    if (box[r].r1 < box[r].r0 || gap == mesh::GapKind::none) continue;
    h[r] = (gap == mesh::GapKind::annular ? box[r].r1 - box[r].r0 : box[r].z1 - box[r].z0) /
           options.gap_layers;
    finest_gap = std::min(finest_gap, h[r]);
  }
  std::vector<double> size(closed.regions.size(), 0.0);
  for (std::size_t r = 0; r < closed.regions.size(); ++r) {
    if (static_cast<int>(r) == closed.geometry.default_region || box[r].r1 < box[r].r0) continue;
    if (h[r] == 0.0) {
      const double side = std::min(box[r].r1 - box[r].r0, box[r].z1 - box[r].z0);
      h[r] = options.region_fraction * side;
      if (std::isfinite(finest_gap)) h[r] = std::max(h[r], finest_gap);
    }
    const double requested = closed.geometry.regions[r].mesh_size;
    if (requested > 0) h[r] = std::min(h[r], requested);
    size[r] = h[r];
  }
  return size;
}

/// TetGen volume limit per region: a regular tetrahedron of the region's size (0: none).
std::vector<double> volume_limits(const std::vector<double>& sizes) {
  std::vector<double> limit(sizes.size(), 0.0);
  for (std::size_t r = 0; r < sizes.size(); ++r)
    if (sizes[r] > 0) limit[r] = tet_volume(sizes[r]);
  return limit;
}

/// What set each region's element size (for the refusal of a mesh too large to solve).
std::vector<std::string> size_reasons_3d(const cases::Problem& closed,
                                         const std::vector<double>& sizes,
                                         const std::vector<double>& cut_sizes,
                                         const std::vector<Feature>& features,
                                         const Solve3dOptions& options) {
  std::vector<std::string> why(sizes.size());
  for (std::size_t r = 0; r < sizes.size(); ++r) {
    const mesh::RegionSeed& region = closed.geometry.regions[r];
    if (r < cut_sizes.size() && cut_sizes[r] > 0 && (sizes[r] <= 0 || cut_sizes[r] <= sizes[r])) {
      for (const Feature& f : features)
        if (f.region == region.name && (f.kind == FeatureKind::hole || f.kind == FeatureKind::port))
          if (std::abs(f.radius / 2.0 - cut_sizes[r]) <= 1e-12 * f.radius) {
            why[r] = "half the radius of " + f.label + ", which cuts this region";
            break;
          }
    } else if (sizes[r] <= 0) {
      why[r] = "the default size, 1/30 of the domain";
    } else if (region.gap != mesh::GapKind::none) {
      why[r] = "the fluid gap's thickness / " + std::to_string(options.gap_layers) + " layers";
    } else if (region.mesh_size > 0 && sizes[r] >= region.mesh_size * (1 - 1e-12)) {
      why[r] = "its mesh_size";
    } else {
      why[r] = "a fraction of its smaller side, no finer than the finest gap";
    }
  }
  return why;
}

/// Largest side of the meridian domain / 30: the 2D mesher's size of regions without one.
double default_meridian_size(const mesh::Mesh& meridian) {
  double r0 = INFINITY, r1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
  for (const mesh::Point& p : meridian.nodes) {
    r0 = std::min(r0, p.r), r1 = std::max(r1, p.r), z0 = std::min(z0, p.z), z1 = std::max(z1, p.z);
  }
  return std::max(r1 - r0, z1 - z0) / 30.0;
}

std::string part_text(ModelPart part, std::size_t steps) {
  const char* name = part == ModelPart::full   ? "full model"
                     : part == ModelPart::half ? "half model"
                                               : "wedge";
  return std::string(name) + ", " + std::to_string(steps) + " angular steps";
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// A Newton step callback reporting to `progress` the step, its relative residual against the
/// tolerance and, from the last step's reduction, the steps and seconds left at that rate (an
/// upper bound while Newton converges faster than linearly); elapsed times from `start`. It
/// holds copies only: the solver keeps it beyond this solve.
std::function<void(int, double)> newton_progress(ProgressCallback progress,
                                                 std::chrono::steady_clock::time_point start,
                                                 double tolerance) {
  const auto newton_start = std::chrono::steady_clock::now();
  auto previous = std::make_shared<double>(1.0);
  return [progress, start, newton_start, previous, tolerance](int steps, double residual) {
    char detail[160];
    const double rate = residual / *previous, spent = seconds_since(newton_start);
    *previous = residual;
    if (residual > tolerance && rate > 0.0 && rate < 1.0) {
      const double left = std::ceil(std::log(tolerance / residual) / std::log(rate));
      std::snprintf(detail, sizeof detail,
                    "relative residual %.2e (tolerance %.0e); at this step's rate at most %.0f "
                    "more step%s, %.0f s",
                    residual, tolerance, left, left == 1.0 ? "" : "s", left * spent / steps);
    } else {
      std::snprintf(detail, sizeof detail, "relative residual %.2e (tolerance %.0e)", residual,
                    tolerance);
    }
    progress({"Newton step " + std::to_string(steps), 0, 0, seconds_since(start), detail});
  };
}

}  // namespace

Solve3dOptions swept_options() {
  Solve3dOptions o;
  o.mesher = Mesher3d::swept;
  o.gap_layers = 3;
  o.region_fraction = 0.2;
  o.facet_angle = 15.0 * std::numbers::pi / 180.0;
  o.fine_angle = 3.0 * std::numbers::pi / 180.0;
  o.angle_growth = 2.0;
  return o;
}

Solve3dResult solve_problem_3d(const cases::Problem& problem, const std::vector<Feature>& features,
                               const Solve3dOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const std::string& source = problem.geometry.source;
  if (problem.symmetry != cases::Symmetry::axisymmetric) {
    throw InputError(source + ": --3d revolves an axisymmetric case; this case is planar");
  }
  if (!(options.gap_layers >= 1) || !(options.region_fraction > 0) || !(options.facet_angle > 0)) {
    throw InputError(source + ": 3D mesh settings must be positive");
  }
  for (const cases::BoundaryCondition& bc : problem.boundaries) {
    if (bc.kind == cases::BoundaryKind::prescribed_a &&
        (bc.a_value != 0.0 || bc.a_per_r != 0.0 || bc.a_per_z != 0.0)) {
      throw InputError(source + ": boundary '" + bc.name +
                       "' prescribes A != 0, which the 3D solver does not support");
    }
  }
  for (const cases::Material& m : problem.materials) {
    // Revolved, a permeability along r and z leaves the one along phi unstated.
    if (m.mu_r_axes && (*m.mu_r_axes)[0] != (*m.mu_r_axes)[1])
      throw InputError(source + ": material '" + m.name +
                       "' is anisotropic (mu_r along r and z differ), which the 3D solver does "
                       "not support; it takes isotropic materials");
  }
  auto report = [&](const char* stage, std::string detail) {
    if (options.progress) options.progress({stage, 0, 0, seconds_since(start), std::move(detail)});
  };
  Solve3dResult out;
  cases::Problem open = problem;
  if (open.outer == cases::OuterBoundary::open) open.outer = cases::OuterBoundary::dirichlet;
  out.closed = magnetostatics::close_domain(open);
  cases::Problem& closed = out.closed;

  report("mesh", "");
  mesh::MeshOptions meridian_options;
  meridian_options.order = 1;
  meridian_options.min_gap_elements = 2;
  const mesh::Mesh meridian = mesh::generate_mesh(closed.geometry, meridian_options);
  const std::vector<RegionBox> boxes = region_boxes(meridian, closed.regions.size());

  // The smallest exact model: a thin wedge for an axisymmetric body (B lies in the meridian
  // planes), the half 0 <= phi <= pi when every feature is symmetric about y = 0, else all.
  ModelPart part = ModelPart::full;
  double span = kTwoPi;
  if (!options.force_full && features.empty()) {
    part = ModelPart::wedge;
    // A swept wedge is one prism layer whatever its angle: the fine step keeps the chords short.
    const double automatic =
        options.mesher == Mesher3d::swept ? options.fine_angle : options.facet_angle;
    span = options.wedge_angle > 0 ? options.wedge_angle : automatic;
  } else if (!options.force_full && features_allow_half_model(features)) {
    part = ModelPart::half;
    span = 0.5 * kTwoPi;
  }
  const std::vector<double> walls = feature_walls(features, closed, boxes, span);
  const std::vector<double> sizes = region_sizes(closed, boxes, options);
  const double max_memory = options.max_memory > 0 ? options.max_memory : default_memory_limit();
  const double default_size = default_meridian_size(meridian);
  mesh::Mesh swept_meridian;
  Revolution swept_revolution;
  if (options.mesher == Mesher3d::swept) {
    // The meridian mesh at the 3D sizes, swept through graded angles (prism layers).
    // Regions holding cuts are refined so the cuts' staircase is a third of their size.
    mesh::Pslg sized = closed.geometry;
    const std::vector<double> cut_sizes = feature_cell_sizes(features, closed);
    std::vector<double> swept_sizes = sizes;
    for (std::size_t r = 0; r < sizes.size(); ++r) {
      double h = sizes[r];
      if (cut_sizes[r] > 0) h = h > 0 ? std::min(h, cut_sizes[r]) : cut_sizes[r];
      if (h > 0) sized.regions[r].mesh_size = h;
      swept_sizes[r] = h;
    }
    swept_revolution = part == ModelPart::wedge
                           ? make_revolution(span, span)
                           : graded_revolution(span, walls, options.fine_angle, options.facet_angle,
                                               options.angle_growth);
    const std::size_t steps = swept_revolution.angles.size() - 1;
    const std::vector<std::string> why =
        size_reasons_3d(closed, sizes, cut_sizes, features, options);
    // Refused before the meridian is meshed at the 3D sizes, then again on its exact count.
    MeshEstimate3d estimate = estimate_swept_mesh(meridian, swept_sizes, default_size, steps);
    estimate.mesher = "swept, " + part_text(part, steps);
    estimate.spread = 2.0;  // from areas, up to 1.4x the count on the bundled valves
    estimate.linear = options.linear;
    require_mesh_within_memory(estimate, max_memory, closed, swept_sizes, why);
    mesh::MeshOptions sweep_options = meridian_options;
    sweep_options.min_gap_elements = options.gap_layers;
    sweep_options.grading = options.meridian_grading;
    swept_meridian = mesh::generate_mesh(sized, sweep_options);
    MeshEstimate3d counted = count_swept_mesh(swept_meridian, sizes.size(), steps);
    counted.mesher = estimate.mesher;
    counted.linear = options.linear;
    require_mesh_within_memory(counted, max_memory, closed, swept_sizes, why);
    out.mesh = std::make_unique<TetMesh>(sweep_mesh(swept_meridian, swept_revolution));
  } else {
    const Revolution rev = make_revolution(span, options.facet_angle, walls);
    MeshEstimate3d estimate = estimate_tetgen_mesh(meridian, sizes, default_size, span);
    estimate.mesher = "TetGen, " + part_text(part, rev.angles.size() - 1);
    estimate.spread = 2.0;
    estimate.linear = options.linear;
    require_mesh_within_memory(estimate, max_memory, closed, sizes,
                               size_reasons_3d(closed, sizes, {}, features, options));
    out.mesh = std::make_unique<TetMesh>(
        tetrahedralize(revolve(closed, rev, volume_limits(sizes), walls)));
  }
  const mesh::Mesh& source_meridian = options.mesher == Mesher3d::swept ? swept_meridian : meridian;
  std::vector<Eigen::Vector3d> undeformed =
      apply_features(features, closed, boxes, span, *out.mesh);
  if (options.mesher == Mesher3d::swept && options.ring_areas) {
    // The coil source follows the mesh: it is evaluated at the undeformed nodes, moved alike.
    const std::vector<Eigen::Vector3d> swept = undeformed;
    restore_ring_areas(out.mesh->nodes, swept, swept_revolution);
    restore_ring_areas(undeformed, swept, swept_revolution);
  }
  out.mesh_seconds = seconds_since(start);

  report("solve", std::to_string(out.mesh->tets.size()) + " tetrahedra, " +
                      std::to_string(out.mesh->edges.size()) + " edges");
  std::vector<int> material_of_region;
  for (const cases::RegionData& r : closed.regions) material_of_region.push_back(r.material);
  Eigen::VectorXd fixed = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(out.mesh->edges.size()));
  Eigen::VectorXd initial;
  if (options.warm_start) {
    report("solve", "2D solution as the start");
    initial = revolved_2d_solution(closed, source_meridian, *out.mesh);
  }
  magnetostatics::NewtonOptions newton = options.newton;
  if (options.linear == LinearSolver3d::ams) {
    newton.max_forcing = options.ams_max_forcing;
    newton.local_max_dofs = options.ams_local_max_dofs;
    newton.local_fraction = options.ams_local_fraction;
  }
  if (options.progress && !newton.on_step)
    newton.on_step = newton_progress(options.progress, start, newton.relative_tolerance);
  out.solver = std::make_unique<EdgeSolver>(
      *out.mesh, magnetostatics::build_reluctivities(closed), material_of_region, fixed,
      circuit_loads(closed, source_meridian, *out.mesh, undeformed), newton,
      options.reuse_iterations, options.linear);
  std::vector<double> currents;
  for (const cases::Circuit& c : closed.circuits) currents.push_back(c.current);
  out.solution = out.solver->solve(currents, initial);
  out.results = compute_results_3d(closed, *out.solver, out.solution, part, span);
  out.results.seconds = seconds_since(start);
  return out;
}

const Results3d& solve_again_at_current_3d(Solve3dResult& solved, double current) {
  const auto start = std::chrono::steady_clock::now();
  // The last solution as it is: scaled by the ratio of the currents it took as many or more
  // Newton steps on the swept wedge of the annular valve (0.9 -> 1 A: 5 against 4; 1 -> 0.5 A:
  // 8 against 6; docs/magnetostatics3d.md).
  const Eigen::VectorXd guess = solved.solution.a;
  const std::vector<double> currents(solved.closed.circuits.size(), current);
  solved.solution = solved.solver->solve(currents, guess);
  const ModelPart part = solved.results.part;
  const double span = solved.results.span;
  solved.results = compute_results_3d(solved.closed, *solved.solver, solved.solution, part, span);
  solved.results.seconds = seconds_since(start);
  return solved.results;
}

}  // namespace rheomag::magnetostatics3d
