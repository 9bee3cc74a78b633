#pragma once
// A step's response from static solves alone, without time stepping the mesh: the quasi-static
// one-mode reduction of the transient problem (docs/transient.md, "Quasi-static response").
// The field is taken to stay a static solution A_s(i_m) of a magnetising current i_m. Galerkin
// projection of
//   M dA/dt + K(A) = F i,   V = R i + dlambda/dt     (M: the conductors' eddy-current matrix)
// onto a' = dA_s/di_m leaves, with L_d = F^T a' = dlambda/di_m and D = a'^T M a',
//   D di_m/dt = L_d (i - i_m):   the eddy currents load the coil like a winding shorted through
//                                the steel, and for a voltage drive
//   di_m/dt = (V - R i_m) / (L_d + R D / L_d).
// The reduction is exact when the field keeps its static shape: steel thin against its skin
// depth over the response time. A linear device's reduced response has the exact one's mean
// delay (first moment, L/R + D/L). It misses the skin effect otherwise (the flux front moving
// into saturating steel); its error against the full transient is measured in the tests and
// docs/transient.md.

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "magnetostatics/frozen_factor.hpp"

#include "transient/transient_solver.hpp"

namespace rheomag::transient {

/// The static state behind the reduction at one magnetising current.
struct QuasiStaticPoint {
  double current = 0.0;             ///< magnetising current i_m [A]
  double flux_linkage = 0.0;        ///< lambda(i_m) [Wb]
  double inductance = 0.0;          ///< L_d = dlambda/di_m [H]
  double eddy_load = 0.0;           ///< D = a'^T M a' [H s], a' = dA/di_m
  std::vector<double> gap_b;        ///< each fluid gap's mean |B| [T]
  std::vector<double> gap_b_slope;  ///< its derivative d|B|/di_m [T/A]
};

/// The static states on a grid of magnetising currents, increasing.
struct QuasiStaticTable {
  std::vector<QuasiStaticPoint> points;
  std::vector<int> gap_regions;  ///< problem regions of the gaps, as in TransientResult::gaps
  int newton_iterations = 0;     ///< of all the static solves
  int linearised = 0;            ///< states found by QuasiStaticReuse::linearise, without Newton
  /// Of those, the states that were the earlier design's own at the same fraction of the range,
  /// without a chord step (a change of the turns alone, the range V / R; QuasiStaticReuse).
  int same_ampere_turns = 0;
};

/// Error of the table's interpolants at a new midpoint (L_d and D relative to their values,
/// lambda and a gap's mean |B| to their largest) up to which its two halves are settled
/// (quasi_static_table).
inline constexpr double kQuasiStaticTableTolerance = 0.05;

/// Static states of the first circuit (the others held) from `low` to `high` [A] (low < high)
/// on `solver`'s mesh: `points` >= 4 equally spaced currents, then each interval's midpoint
/// solved and checked against the table's interpolants before it; where they missed it by more
/// than kQuasiStaticTableTolerance its two halves are checked in turn, until every interval is
/// settled or the table has 16 x `points` currents (so at least 2 `points` - 1; saturation knees
/// far below `high` are found). Each is a
/// static solve started from its neighbours' states and slopes (the tangent predictor; cubic
/// Hermite between two), with its dA/dI and its eddy-current load from
/// `solver`'s conductivities and remedies. InputError for bad arguments; ConvergenceError when
/// a static solve fails.
QuasiStaticTable quasi_static_table(TransientSolver& solver, double low, double high, int points);

/// The static states of a table (nodal A at each current), kept to start the table of a nearby
/// design on a mesh of the same topology (an optimiser's morphed mesh).
struct QuasiStaticStart {
  std::vector<double> fractions;        ///< (current - low) / (high - low) of each state
  std::vector<double> currents;         ///< its current [A]
  std::vector<Eigen::VectorXd> fields;  ///< its nodal A [Wb/m]
  std::vector<Eigen::VectorXd> slopes;  ///< its nodal dA/di_m [Wb/(m A)]
  /// The factorisation of the tangent at each state (QuasiStaticReuse::keep_factor_bytes; null
  /// beyond the budget), else empty.
  std::vector<std::shared_ptr<const magnetostatics::FrozenFactor>> factors;
  /// With factors: the residual R(A) Newton left at each state (free dofs).
  std::vector<Eigen::VectorXd> residuals;
};

/// How quasi_static_table reuses an earlier design's table.
struct QuasiStaticReuse {
  /// Warm starts: each static solve starts from this table's state at the nearest current,
  /// moved along its slope, when that has the smaller residual than the table's own prediction
  /// (ignored unless its fields have this mesh's node count). The table is the one built without
  /// it, to Newton's tolerance.
  const QuasiStaticStart* start = nullptr;
  /// With `start`: its fractions are the grid, not refined. For a finite-difference neighbour
  /// of the design that built `start`: both tables then have the same grid, so their difference
  /// is smooth in the design.
  bool fixed_grid = false;
  /// With `start` on its fixed grid: each state whose earlier state kept its factorisation is
  /// linearised about it, without Newton: chord steps with the earlier tangent's factorisation to
  /// Newton's tolerance, and dA/di_m of this design, both to second order in the designs'
  /// difference (the table a finite-difference neighbour needs; docs/transient.md, "Linearised
  /// neighbours"). A state whose chord steps do not converge in 4 is solved by Newton from them.
  /// From 0 A, each earlier state at the same fraction of the range is tried first and taken
  /// when its residual is within Newton's tolerance (the same ampere-turns after a change of
  /// the turns alone with the range V / R), until one is not.
  bool linearise = false;
  QuasiStaticStart* keep = nullptr;  ///< when given, filled with this table's states
  /// With `keep`: also keep each state's tangent factorisation, in the order the states are
  /// solved (the starting currents from the lowest, then the midpoints), while they hold at most
  /// this many bytes in all (0: none).
  std::size_t keep_factor_bytes = 0;
};

/// quasi_static_table(solver, low, high, points) reusing an earlier design's states as `reuse`
/// says.
QuasiStaticTable quasi_static_table(TransientSolver& solver, double low, double high, int points,
                                    const QuasiStaticReuse& reuse);

/// The rise times of one step in the reduction.
struct QuasiStaticStep {
  std::vector<std::optional<double>> gap_t63, gap_t90;  ///< per gap, of its mean |B| [s]
  std::optional<double> t63, t90;                       ///< of the flux linkage [s]
  std::vector<double> gap_b_from, gap_b_final;          ///< per gap, mean |B| before and after [T]
};

/// Response to a step of the first circuit from the steady state at `from_current` to the one
/// at `final_current` [A]: a voltage step V = R final_current through `resistance` R [Ohm], or
/// an ideal current step for R = infinity. Gives the times at which each gap's mean |B| (and
/// lambda) first make 63 % and 90 % of their change: the quantities interpolated between the
/// table's currents (cubic Hermite through values and slopes, PCHIP for L_d and D) and
/// t(i_m) = integral (L_d / R + D / L_d) du, u = -ln((final - i_m) / (final - from)), by
/// Gauss-Legendre quadrature. The table must span both currents; InputError otherwise.
QuasiStaticStep quasi_static_step(const QuasiStaticTable& table, double from_current,
                                  double final_current, double resistance);

}  // namespace rheomag::transient
