#pragma once
// Steady-state valve chain: a case's magnetised gaps in series, each with the FE flux density
// along its mid-line, plus the coil; pressure drop and coil quantities per (current, flow).

#include <memory>
#include <string>
#include <vector>

#include "fluid/coil.hpp"
#include "fluid/field_coupling.hpp"
#include "fluid/fluid.hpp"
#include "fluid/passage.hpp"
#include "magnetostatics/case_file.hpp"
#include "magnetostatics/solve_problem.hpp"

namespace rheomag::fluid {

/// Options of the [valve] table of a case file (docs/fluid.md); all optional except where noted.
struct ValveOptions {
  std::string wire;               ///< wire gauge, e.g. "AWG 24" (needed for the coil resistance)
  double temperature = 20.0;      ///< coil temperature [deg C]
  double inlet_radius = 0.0;      ///< radial gaps starting on the axis start here instead [m]
  std::vector<double> flows;      ///< default flow rates [m^3/s]
  std::vector<Passage> passages;  ///< unmagnetised passages in series ([[valve.passage]])
  std::vector<MinorLoss> losses;  ///< minor losses in series ([[valve.loss]])
};

/// Reads the [valve] table of a case (absent: defaults). InputError names unknown keys.
ValveOptions read_valve_options(const magnetostatics::Case& c);

/// One gap segment's result at one operating point.
struct SegmentResult {
  std::string name;
  std::string kind;              ///< "annular", "radial" (gaps), "passage" or "loss"
  double b_average = 0.0;        ///< mean |B_n| along the mid-line [T] (0 for passages and losses)
  FieldCoupledDrop drop;         ///< field-integrated and one-average-B pressure drops
  double reynolds_number = 0.0;  ///< passages: rho V D_h / mu (laminar formulas: < ~2000)
};

/// One operating point of the valve.
struct ValvePoint {
  double current = 0.0, flow = 0.0;
  double dp_total = 0.0, dp_yield = 0.0, dp_viscous = 0.0;  ///< field-integrated [Pa]
  double dp_total_average_b = 0.0;                          ///< one-average-B shortcut [Pa]
  double flux_linkage = 0.0;                                ///< lambda of circuit 0 [Wb]
  double inductance = 0.0;                                  ///< secant lambda/I of circuit 0 [H]
  double incremental_inductance = 0.0;  ///< dlambda/dI of circuit 0 [H] (NaN if not computed)
  std::vector<SegmentResult> segments;
};

/// A case's valve: mesh and solver set up once, then any number of operating points. (For a
/// field that is already solved, use SolvedValve in fluid/solved_valve.hpp.)
class ValveChain {
 public:
  /// Meshes the case and prepares the solver (no solve yet); InputError if it has no gap, no
  /// coil or no fluid.
  ValveChain(const magnetostatics::Case& c, ValveOptions options);
  /// Solves the field once at each current and evaluates every flow in it with SolvedValve
  /// (current-major order).
  std::vector<ValvePoint> evaluate(const std::vector<double>& currents,
                                   const std::vector<double>& flows);
  /// Coil quantities at `current` with inductance `inductance` (needs ValveOptions::wire).
  CoilProperties coil(double current, double inductance) const;
  /// The fluid of the gaps.
  const Fluid& fluid() const { return fluid_; }
  /// The turns of the first circuit.
  double turns() const { return coil_.turns; }

 private:
  std::unique_ptr<magnetostatics::MagnetostaticSolver> solver_;
  Fluid fluid_;
  ValveOptions options_;
  CoilSpec coil_;
};

}  // namespace rheomag::fluid
