#pragma once
// The response_time quantity: how fast a design's gap field follows its driver's voltage step,
// with the eddy currents in its steel (transient magnetics, docs/transient.md).

#include "case/case_file.hpp"
#include "core/progress.hpp"
#include "magnetostatics/solver.hpp"
#include "transient/quasi_static.hpp"

namespace rheomag::design {

/// Settings of the two step responses behind response_time.
struct ResponseTimeOptions {
  double supply_voltage = 0.0;  ///< driver voltage step [V] (> 0)
  double resistance = 0.0;      ///< coil resistance [Ohm] (> 0)
  double time_constant = 0.0;   ///< L / R of the coil [s] (> 0), sets the simulated span
  /// First simulated span as a multiple of `time_constant` (doubled up to 3 times while a gap
  /// has not made 90 % of its change).
  double span_factor = 5.0;
  int steps = 100;  ///< equal midpoint steps per span (smooth in the design for gradients)
  /// true: the quasi-static reduction (transient/quasi_static.hpp) on static solves from 0 to
  /// V / R (`table_points` equal currents, refined) instead of the two transient runs.
  bool quasi_static = false;
  int table_points = 8;  ///< quasi-static: the table's starting currents
  /// quasi-static: an earlier design's table to start from, and where to keep this one's
  /// (transient::QuasiStaticReuse).
  transient::QuasiStaticReuse reuse;
  /// Transient runs: one report per accepted step, stage "switch-on, ..." or "switch-off, ...",
  /// done in per cent of the simulated span (total 100, a bound: the run ends at the slowest
  /// gap's t90), elapsed since the run started.
  ProgressCallback progress;
};

/// The two step responses' t90 [s] and the transient solves they took.
struct ResponseTime {
  double on = 0.0;   ///< 0 -> V: slowest gap's mean |B| reaches 90 % of its change
  double off = 0.0;  ///< V -> 0 from the steady state at V / R
  int transient_runs = 0;
  int static_solves = 0;  ///< quasi-static: the table's solves (after its refinement)
  double value() const { return on > off ? on : off; }  ///< the slower of the two
};

/// t90 of every fluid gap's mean |B| after a voltage step 0 -> V and V -> 0 on the first
/// circuit through its resistance, from `rheomag transient`'s solver on `statics` (eddy
/// currents with the case's conductivities and [transient] remedies); the slowest gap counts.
/// With `options.quasi_static` both steps come from one table of static solves (no time
/// stepping; its error against the transient runs in docs/transient.md).
/// InputError for missing conductivities or bad options; ConvergenceError when a step fails or
/// 90 % is not reached within 8 spans (the reduction: not reached at all).
ResponseTime response_time(magnetostatics::MagnetostaticSolver& statics, const cases::Case& c,
                           const ResponseTimeOptions& options);

}  // namespace rheomag::design
