#pragma once
// A valve whose magnetic field is already solved: the gaps' geometry and mid-line flux density
// sampled once from the FE solution, then the pressure drop of the whole flow path at any flow
// rate without another field solve (used by ValveChain, sweeps and the optimiser).

#include <optional>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "fluid/field_coupling.hpp"
#include "fluid/fluid.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"
#include "valve/coil.hpp"
#include "valve/sampled_gaps.hpp"
#include "valve/valve_chain.hpp"

namespace rheomag::valve {

/// The MR fluid named by the case ([case] fluid, from the material library); InputError if none.
fluid::Fluid case_fluid(const cases::Case& c);

/// Coil of circuit 0 from the solver's mesh: turns (sum of |turns| of its regions), winding
/// window area and mean turn length (2 pi x area-weighted mean radius), plus the wire diameter
/// (0 without ValveOptions::wire) and temperature of `options`. InputError without turns.
CoilSpec coil_spec(const magnetostatics::MagnetostaticSolver& solver, const ValveOptions& options);

/// Resistance of the case's coil at its [valve] temperature from its [valve] wire and the
/// winding in the solver's mesh; nothing when the case names no wire.
std::optional<double> wire_resistance(const cases::Case& c,
                                      const magnetostatics::MagnetostaticSolver& solver);

/// The flow path of a solved design: every magnetised gap (RegionSeed::gap) in series with the
/// normal flux density |B_n| at 101 mid-line points, then the unmagnetised passages and minor
/// losses of ValveOptions (dimensions of region passages from the mesh). Copies what it needs:
/// the solver, solution and results may be destroyed afterwards.
class SolvedValve {
 public:
  /// Samples every gap of `results` in `solution`; InputError if there is no gap, a gap has
  /// fewer than 2 samples, a radial gap starts on the axis without [valve] inlet_radius, or a
  /// passage's region or a loss's section does not exist or does not fit.
  SolvedValve(const magnetostatics::MagnetostaticSolver& solver,
              const magnetostatics::Solution& solution, const magnetostatics::Results& results,
              const fluid::Fluid& fluid, const ValveOptions& options);
  /// Pressure drop at `flow` [m^3/s] in the solved field (current, flux linkage and
  /// inductances of circuit 0 from the solution).
  ValvePoint point(double flow) const;
  /// The same flow path with B = 0 in every gap (the off-state of this geometry).
  ValvePoint zero_field_point(double flow) const;
  /// Mean of |B_n| over all gaps' mid-line samples [T].
  double b_average() const { return b_average_; }
  /// Smallest gap clearance [m].
  double min_clearance() const { return min_clearance_; }

 private:
  struct Loss {
    fluid::MinorLoss loss;
    double area = 0.0;  ///< of the named section [m^2]
  };
  ValvePoint evaluate(double flow, bool zero_field) const;
  double section_area(const fluid::MinorLoss& loss) const;
  std::vector<SampledGap> gaps_;
  std::vector<fluid::Passage> passages_;  ///< dimensions resolved
  std::vector<Loss> losses_;
  fluid::Fluid fluid_;
  ValveOptions options_;
  double current_ = 0.0, flux_linkage_ = 0.0, inductance_ = 0.0, incremental_ = 0.0;
  double b_average_ = 0.0, min_clearance_ = 0.0;
};

}  // namespace rheomag::valve
