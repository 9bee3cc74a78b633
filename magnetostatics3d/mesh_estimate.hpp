#pragma once
// The size of a 3D mesh and of its solve, estimated before the work, and the refusal of a mesh
// whose solve would not fit in the memory allowed (Solve3dOptions::max_memory, --max-memory).

#include <string>
#include <vector>

#include "case/problem.hpp"
#include "magnetostatics3d/edge_solver.hpp"
#include "mesh/mesh.hpp"

namespace rheomag::magnetostatics3d {

/// Estimated tetrahedra of a 3D mesh, per region of the closed problem.
struct MeshEstimate3d {
  std::vector<double> region_tetrahedra;
  std::string mesher;   ///< "swept, full model, 96 angular steps" for messages
  double spread = 1.0;  ///< how far the estimate may exceed the count (1: exact); a mesh is
                        ///< refused when its memory over this exceeds the limit
  LinearSolver3d linear = LinearSolver3d::cholmod;  ///< the solve's (its memory differs)

  /// Sum over the regions.
  double tetrahedra() const;
};

/// Estimated peak memory [bytes] of a 3D solve with `tetrahedra` first-order Nedelec elements:
/// the mesh, the edge system and, with CHOLMOD, its Cholesky factor; with AMS, hypre's copy of
/// the system and its auxiliary hierarchies, linear in the size (measured,
/// docs/magnetostatics3d.md).
double solve_memory_bytes(double tetrahedra, LinearSolver3d linear = LinearSolver3d::cholmod);

/// TetGen: per region, its volume of revolution over `span` [rad] (from the linear `meridian`
/// mesh) over the volume of a regular tetrahedron of its size `sizes[r]` [m], times the measured
/// ratio of TetGen's elements to that count; regions without a size at `default_size`.
MeshEstimate3d estimate_tetgen_mesh(const mesh::Mesh& meridian, const std::vector<double>& sizes,
                                    double default_size, double span);

/// Swept mesher before the meridian is meshed at `sizes`: three tetrahedra per prism, the
/// triangles of each region estimated from its meridian area as the 2D mesher does.
MeshEstimate3d estimate_swept_mesh(const mesh::Mesh& meridian, const std::vector<double>& sizes,
                                   double default_size, std::size_t angular_steps);

/// Swept mesher once the meridian is meshed: three tetrahedra per triangle and angular step.
MeshEstimate3d count_swept_mesh(const mesh::Mesh& sized_meridian, std::size_t regions,
                                std::size_t angular_steps);

/// Throws InputError when solve_memory_bytes(estimate) exceeds `max_memory` [bytes]. The message
/// names the estimate (tetrahedra and bytes), the limit, the region holding most tetrahedra,
/// its element size and what set it (`size_reasons[r]`).
void require_mesh_within_memory(const MeshEstimate3d& estimate, double max_memory,
                                const cases::Problem& closed, const std::vector<double>& sizes,
                                const std::vector<std::string>& size_reasons);

}  // namespace rheomag::magnetostatics3d
