#pragma once
// One call from an axisymmetric Problem (plus non-axisymmetric features) to 3D results.

#include <memory>
#include <vector>

#include "case/problem.hpp"
#include "core/enum_names.hpp"
#include "core/progress.hpp"
#include "magnetostatics/newton.hpp"
#include "magnetostatics3d/edge_solver.hpp"
#include "magnetostatics3d/features.hpp"
#include "magnetostatics3d/results3d.hpp"
#include "magnetostatics3d/tet_mesh.hpp"

namespace rheomag::magnetostatics3d {

/// How the revolved body is cut into tetrahedra.
enum class Mesher3d {
  tetgen,  ///< TetGen on the revolved surfaces: graded isotropic tetrahedra
  swept,   ///< the meridian triangle mesh swept through graded angles: prism layers split into
           ///< tetrahedra, long in phi where the angular steps are coarse
};

/// Text form of Mesher3d (the CLI's --mesher).
inline constexpr auto kMesher3dNames =
    enum_names<Mesher3d>({{Mesher3d::tetgen, "tetgen"}, {Mesher3d::swept, "swept"}});

/// Mesh and solver settings of a 3D solve.
struct Solve3dOptions {
  int gap_layers = 3;             ///< tetrahedron edge length in a fluid gap = thickness / this
  double region_fraction = 0.15;  ///< other regions: edge length = this x smallest side of the
                                  ///< region's meridian bounding box
  double wedge_angle = 0.0;       ///< wedge of an axisymmetric body [rad]; 0 = automatic
                                  ///< (facet_angle; swept: fine_angle)
  double facet_angle = 5.0 * 3.14159265358979323846 / 180.0;  ///< largest angle of a revolved
                                                              ///< facet [rad]
  Mesher3d mesher = Mesher3d::tetgen;
  double fine_angle = 1.5 * 3.14159265358979323846 / 180.0;  ///< swept: angular step at a
                                                             ///< feature's edge [rad]
  double angle_growth = 1.5;      ///< swept: growth of the angular step per step away from an edge,
                                  ///< up to facet_angle
  double meridian_grading = 0.6;  ///< swept: size growth of the meridian triangles per unit
                                  ///< distance from finer regions (mesh::MeshOptions::grading)
  bool ring_areas = true;         ///< swept: move the nodes out radially so that the facetted
                                  ///< rings keep their true areas (restore_ring_areas)
  bool force_full = false;        ///< mesh the whole revolution even when a symmetry allows less
  double max_memory = 0.0;        ///< refuse (InputError, before meshing) a mesh whose solve is
                                  ///< estimated to need more [bytes]; 0 = default_memory_limit()
  /// Start Newton from the case's axisymmetric 2D solution revolved onto the edges
  /// (warm_start.hpp) instead of A = 0. With the local corrections (NewtonOptions) the start's
  /// error at a feature (the slot's air carries the steel's 2D flux) is taken out where it sits:
  /// on the lead-slot half model 7 Newton steps and 77 AMS-CG iterations instead of 8 and 120, on
  /// the annular valve's wedge 4 steps and 2 factorisations instead of 10 and 4
  /// (docs/magnetostatics3d.md). Without the corrections it took 10 steps instead of 8.
  bool warm_start = true;
  /// Conjugate-gradient budget per Newton step with the last factorisation as preconditioner
  /// before the step factorises its own tangent (EdgeSolver); 0: factorise every step.
  int reuse_iterations = 20;
  /// How each Newton step's linear system is solved (EdgeSolver).
  LinearSolver3d linear = LinearSolver3d::cholmod;
  /// With LinearSolver3d::ams, Newton's largest forcing term (replaces newton.max_forcing): each
  /// step's CG stops at this relative residual until Newton's own residual is smaller. Tight
  /// enough that what a step leaves is its nonlinear residual, concentrated where the steel
  /// saturates, so the local corrections below take it (docs/performance.md, session 49).
  double ams_max_forcing = 0.01;
  /// With LinearSolver3d::ams, the local corrections' seed edges (replace newton.local_max_dofs
  /// and local_fraction): the residual is spread over every free edge, not the cotree's fewer
  /// unknowns, so after a step 500 edges hold 82-90 % of |R|^2 where 2 000 hold over 80 %. With
  /// both, the lead-slot half model takes 5 Newton steps instead of 8 (14.1-15.0 s, was
  /// 15.8-16.9 s alternated).
  int ams_local_max_dofs = 2000;
  double ams_local_fraction = 0.8;  ///< share of |R|^2 the seeds must hold (see above)
  magnetostatics::NewtonOptions newton;
  ProgressCallback progress;  ///< stages "mesh", "solve" (optional)
};

/// Settings of the swept mesher for half and full models of valves with features: three layers
/// across a gap, regions at 0.2 of their smaller side, 15-degree angular steps refined to
/// 3 degrees at a feature's edges (growth 2), rings restored to their true areas. The bundled
/// annular valve's lead-slot half model (351k tetrahedra) matches 2D within 1 % in the flux
/// linkage and in every 10-degree sector of the gap field where the body is axisymmetric
/// (docs/magnetostatics3d.md).
Solve3dOptions swept_options();

/// Everything a 3D solve produces (the mesh and solver stay alive for .vtu output).
struct Solve3dResult {
  cases::Problem closed;  ///< the problem with its outer boundary (region indices of the mesh)
  std::unique_ptr<TetMesh> mesh;
  std::unique_ptr<EdgeSolver> solver;
  EdgeSolution solution;
  Results3d results;
  double mesh_seconds = 0.0;
};

/// Revolves `problem` (axisymmetric) about z, cuts the `features`, meshes it with TetGen and
/// solves the 3D field at the problem's circuit currents. Without features the body is
/// axisymmetric and a thin wedge is meshed; with features all at 0 or 180 degrees the half
/// 0 <= phi <= pi (unless options.force_full). The outer boundary of the 2D case becomes a sphere
/// of the same radius with tangential A = 0 (the 2D open condition is not carried over: for the
/// bundled valves the difference at outer_radius_factor 5 is below 1e-4 in lambda and the gap
/// |B|, docs/magnetostatics3d.md). Throws InputError for bad input (including TetGen failures
/// and a mesh whose solve is estimated to need more than options.max_memory, refused before the
/// 3D mesh is made: mesh_estimate.hpp) and ConvergenceError if Newton fails.
Solve3dResult solve_problem_3d(const cases::Problem& problem,
                               const std::vector<Feature>& features = {},
                               const Solve3dOptions& options = {});

/// Solves the model of `solved` again with `current` [A] in every circuit, on the same mesh and
/// symbolic analysis, with the last factorisation as CG preconditioner while it serves (the
/// options it was made with), from its last solution. Replaces solved.solution and
/// solved.results and returns the results; their seconds are this solve's alone. Throws
/// ConvergenceError if Newton fails.
const Results3d& solve_again_at_current_3d(Solve3dResult& solved, double current);

}  // namespace rheomag::magnetostatics3d
