#pragma once
// Steady-state valve chain: a case's magnetised gaps in series, each with the FE flux density
// along its mid-line, plus the coil; pressure drop and coil quantities per (current, flow).

#include <memory>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "core/enum_names.hpp"
#include "fluid/field_coupling.hpp"
#include "fluid/fluid.hpp"
#include "fluid/passage.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "valve/coil.hpp"
#include "valve/device_chain.hpp"
#include "valve/valve_options.hpp"

namespace rheomag::valve {

/// What a segment of the valve's flow path is.
enum class SegmentKind {
  annular,  ///< a magnetised annular gap
  radial,   ///< a magnetised radial gap
  passage,  ///< an unmagnetised passage ([[valve.passage]])
  loss,     ///< a minor loss ([[valve.loss]])
};

/// The segment kinds' names in outputs.
inline constexpr auto kSegmentKindNames = enum_names<SegmentKind>({
    {SegmentKind::annular, "annular"},
    {SegmentKind::radial, "radial"},
    {SegmentKind::passage, "passage"},
    {SegmentKind::loss, "loss"},
});

/// One gap segment's result at one operating point.
struct SegmentResult {
  std::string name;
  SegmentKind kind = SegmentKind::annular;
  double b_average = 0.0;        ///< mean |B_n| along the mid-line [T] (0 for passages and losses)
  fluid::FieldCoupledDrop drop;  ///< field-integrated and one-average-B pressure drops
  double reynolds_number = 0.0;  ///< passages: rho V D_h / mu (laminar formulas: < ~2000)
  fluid::GapFieldSamples field;  ///< gaps: the |B_n| along the mid-line the drop integrated
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
class ValveChain : public DeviceChain {
 public:
  /// Meshes the case and prepares the solver (no solve yet); InputError if it has no gap, no
  /// coil or no fluid.
  ValveChain(const cases::Case& c, ValveOptions options);
  /// Solves the field once at each current and evaluates every flow in it with SolvedValve
  /// (current-major order).
  std::vector<ValvePoint> evaluate(const std::vector<double>& currents,
                                   const std::vector<double>& flows);
  /// The turns of the first circuit.
  double turns() const { return coil_.turns; }
};

}  // namespace rheomag::valve
