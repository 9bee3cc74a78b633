#pragma once
// Post-processing of a magnetostatic solution: fields, fluid-gap flux densities, circuit
// quantities (flux linkage, inductances) and energies.

#include <optional>
#include <string>
#include <vector>

#include "magnetostatics/solver.hpp"
#include "mesh/pslg.hpp"

namespace rheomag::magnetostatics {

/// Average, minimum and maximum of a scalar field.
struct FieldStats {
  double average = 0.0;
  double minimum = 0.0;
  double maximum = 0.0;
};

/// B along one line of a gap: distance from the line's start and the flux density's components
/// normal (B_r for an annular gap, B_z for a radial one) and tangential to the walls, signed.
struct GapProfile {
  std::vector<double> s;         ///< [m]
  std::vector<double> b_n, b_t;  ///< [T]
};

/// Flux density in one fluid-gap region (RegionSeed::gap != none) [T].
/// Normal component: B_r for an annular gap (walls r = const), B_z for a radial gap (walls
/// z = const); statistics of its magnitude |B_n|.
struct GapResult {
  std::string name;
  mesh::GapKind kind = mesh::GapKind::none;
  int region = -1;
  double area = 0.0;  ///< meridian-plane area [m^2]
  FieldStats b;       ///< |B| over the area: area-weighted average, min/max over quadrature points
  FieldStats b_normal;               ///< |B_n| over the area, same rules
  FieldStats line_b;                 ///< |B| along the mid-line: mean, min, max of the samples
  FieldStats line_b_normal;          ///< |B_n| along the mid-line
  mesh::Point line_start, line_end;  ///< mid-line of the gap's bounding box (long direction)
  int line_samples = 0;              ///< samples found inside the gap (by point location)
  GapProfile profile;                ///< the mid-line samples that line_b summarises
  /// The same along the gap's two walls (the sides of its bounding box parallel to the
  /// mid-line: smaller r or z first), where they bound the gap.
  std::array<GapProfile, 2> walls;
};

/// Quantities of one series circuit.
struct CircuitResult {
  std::string name;
  double current = 0.0;                 ///< [A]
  double turns = 0.0;                   ///< total turns of its regions (signed sum)
  double flux_linkage = 0.0;            ///< lambda = sum_regions (2 pi N / A) integral A r dA [Wb]
  double inductance = 0.0;              ///< secant lambda / I [H] (incremental at I = 0)
  double incremental_inductance = 0.0;  ///< dlambda/dI at the solution [H] (NaN if not computed)
  /// False when lambda depends on the gauge (MagnetostaticSolver::flux_linkage_gauge_free): then
  /// flux_linkage and the inductances are NaN (not reported).
  bool gauge_free = true;
  /// What makes the values meaningless, e.g. a driven circuit that winds no region ("": none).
  std::string warning;
};

/// All results of one solve. Fields per element are the element averages of B (area-weighted),
/// H(B) of that average and mu_r = |B| / (mu0 |H|) (1 / (mu0 nu) when isotropic); nodal fields
/// are area-weighted averages over the elements sharing the node of each element's own value at
/// the node.
struct Results {
  std::vector<double> element_br, element_bz, element_b;  ///< [T]
  std::vector<double> element_hr, element_hz, element_h;  ///< [A/m]
  std::vector<double> element_mu_r;
  std::vector<double> node_br, node_bz, node_b, node_hr, node_hz, node_h, node_mu_r;
  std::vector<GapResult> gaps;
  std::vector<CircuitResult> circuits;
  /// W = integral integral_0^B H dB dV [J] over the mesh, plus the energy of the mixed
  /// boundary terms (open boundary: the exterior dipole-field energy; linear there, so it is
  /// added to the co-energy too).
  double energy = 0.0;
  double coenergy = 0.0;  ///< W' = integral B . H dV - W [J] (+ the same exterior term)
  int newton_iterations = 0;
  std::vector<double> residual_history;  ///< relative residual per Newton iterate
  int dofs = 0;
  int elements = 0;
  int nodes = 0;
  double seconds = 0.0;  ///< solve wall time
};

/// Number of mid-line samples per gap.
inline constexpr int kGapLineSamples = 201;

/// Evaluates all results of `solution` (computed by `solver`).
Results compute_results(const MagnetostaticSolver& solver, const Solution& solution);

/// MagnetostaticSolver::sweep with each point's gap flux densities (B_avg, B_max_midline,
/// B_max_area) from compute_results.
std::vector<SweepPoint> sweep_with_gaps(MagnetostaticSolver& solver, int circuit,
                                        const std::vector<double>& currents);

/// A point of the mesh: its triangle and reference coordinates (xi, eta) there.
struct MeshLocation {
  int element = -1;
  double xi = 0.0, eta = 0.0;
};

/// The first triangle of region `region` (-1: any region) containing `p` (boundary included),
/// by a linear search; nothing if no such triangle contains it.
std::optional<MeshLocation> locate_in_mesh(const mesh::Mesh& m, mesh::Point p, int region = -1);

/// Flux density (B_r, B_z) [T] at a located point.
std::array<double, 2> flux_density_in(const MagnetostaticSolver& solver, const Solution& solution,
                                      const MeshLocation& at);

/// Flux density (B_r, B_z) at a point of region `region` (-1: any region) [T], by point location;
/// false if the point is in no such triangle.
bool flux_density_at(const MagnetostaticSolver& solver, const Solution& solution, mesh::Point p,
                     int region, std::array<double, 2>& b);

}  // namespace rheomag::magnetostatics
