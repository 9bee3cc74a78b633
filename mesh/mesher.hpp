#pragma once
// Quality triangulation of a PSLG: CGAL constrained Delaunay refinement with per-region sizes.

#include "core/progress.hpp"
#include "mesh/mesh.hpp"
#include "mesh/pslg.hpp"

namespace rheomag::mesh {

/// Smallest angle [deg] of CGAL's default shape bound B = sin^2(angle) = 0.125.
inline constexpr double kDefaultMinAngleDeg = 20.70481105463543;

/// Options of generate_mesh (lengths in metres).
struct MeshOptions {
  int order = 2;                           ///< 1 = linear, 2 = quadratic (6-node) triangles
  double min_angle = kDefaultMinAngleDeg;  ///< lower bound on triangle angles [deg], (0, 30]
  double default_size = 0.0;               ///< target edge length of regions without
                                           ///< mesh_size; 0 = longest bounding-box side / 30
  int min_gap_elements = 4;                ///< elements across every fluid-gap region (>= 1)
  /// Every target size (regions, default, fluid gaps) times this: 2 gives a copy of the mesh with
  /// about a quarter of the nodes (the coarser levels of a nested solve). > 0.
  double size_scale = 1.0;
  double grading = 0.3;           ///< size growth per unit distance from a finer
                                  ///< region or segment; 0 = no grading
  long max_elements = 5'000'000;  ///< refuse (InputError) meshes estimated larger
  double max_memory = 0.0;        ///< refuse meshes whose solve is estimated to need
                                  ///< more [bytes]; 0 = default_memory_limit()
  /// Hears the meshing's progress: the checked geometry, then triangles made (twice the
  /// vertices) of the estimate every 20 000 points inserted, and the end (the same mesh as
  /// without it). Empty: no reports.
  ProgressCallback progress;
};

/// Memory a 2D solve needs per triangle of `order` [bytes], for the estimate before meshing:
/// measured peak resident memory of `bench_solve` (1.14 GiB at 1e6 P2 unknowns, about 2 per
/// triangle; docs/performance.md) and half as much again for the mesher and the results.
double solve_bytes_per_triangle(int order);

/// Meshes the PSLG: validates it (InputError naming Pslg::source), labels each enclosed area
/// with its region, refines to the size and angle criteria and returns a mesh of `order`.
/// Deterministic: the same input gives the same nodes and triangles in the same order.
Mesh generate_mesh(const Pslg& pslg, const MeshOptions& options = {});

}  // namespace rheomag::mesh
