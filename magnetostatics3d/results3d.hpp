#pragma once
// Post-processing of a 3D solution: fluid-gap flux densities with their circumferential profile,
// circuit flux linkage and inductance, energy.

#include <array>
#include <string>
#include <vector>

#include "case/problem.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics3d/edge_solver.hpp"
#include "magnetostatics3d/revolve.hpp"

namespace rheomag::magnetostatics3d {

/// Number of circumferential sectors of B_avg_theta (10 degrees each).
inline constexpr int kThetaSectors = 36;

/// Which part of the revolved body is meshed; results are always for the whole body.
enum class ModelPart {
  wedge,  ///< a thin wedge with symmetry planes: exact for an axisymmetric body
  half,   ///< 0 <= phi <= pi, the plane y = 0 a symmetry plane (features at 0 or 180 degrees)
  full,   ///< the whole revolution
};

/// Flux density in one fluid gap [T]. Averages are weighted by meridian area (volume / r), the
/// same weighting as the 2D area averages; minimum and maximum are over tetrahedra.
struct GapResult3d {
  std::string name;
  mesh::GapKind kind = mesh::GapKind::none;
  int region = -1;
  double volume = 0.0;                              ///< of the whole body's gap [m^3]
  magnetostatics::FieldStats b;                     ///< |B|
  magnetostatics::FieldStats b_normal;              ///< |B_r| (annular) or |B_z| (radial)
  std::array<double, kThetaSectors> b_avg_theta{};  ///< average |B| per 10-degree sector
};

/// Flux linkage and secant inductance of one circuit.
struct CircuitResult3d {
  std::string name;
  double current = 0.0;       ///< [A]
  double flux_linkage = 0.0;  ///< [Wb], whole body
  double inductance = 0.0;    ///< lambda / I [H] (NaN at I = 0)
};

/// All results of one 3D solve (whole-body values whatever part is meshed).
struct Results3d {
  ModelPart part = ModelPart::full;
  double span = 0.0;  ///< meshed angle [rad]
  std::vector<GapResult3d> gaps;
  std::vector<CircuitResult3d> circuits;
  double energy = 0.0;  ///< integral integral_0^B H dB dV [J]
  int dofs = 0;
  int tetrahedra = 0;
  int nodes = 0;
  int edges = 0;
  int newton_iterations = 0;
  LinearSolver3d linear_solver = LinearSolver3d::cholmod;  ///< how the Newton steps were solved
  int factorizations = 0;  ///< numeric Cholesky factorisations (AMS: set-ups) of the solve
  int cg_iterations = 0;   ///< CG iterations (on a reused factorisation, or AMS-preconditioned)
  std::vector<double> residual_history;
  double seconds = 0.0;  ///< mesh and solve wall time
};

/// Evaluates the results of `solution` for `closed` (the revolved problem; region indices of the
/// mesh are those of closed.regions).
Results3d compute_results_3d(const cases::Problem& closed, const EdgeSolver& solver,
                             const EdgeSolution& solution, ModelPart part, double span);

}  // namespace rheomag::magnetostatics3d
